// threads.h: set_threads checks its argument, and 0 restores the default. That results do not
// depend on the thread count: test_solver.cpp; msmesh --threads: cli/test_threads_cli.cpp.
#include <gtest/gtest.h>

#include <string>

#include "msmesh/errors.h"
#include "msmesh/threads.h"

using namespace msmesh;

TEST(Threads, SetThreadsChecksItsArgumentAndRestoresTheDefault) {
  const int initial = msmesh::threads();
  EXPECT_GE(initial, 1);
  for (const int bad : {-1, 4097}) {
    try {
      set_threads(bad);
      FAIL() << "no error for " << bad;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("threads: " + std::to_string(bad)), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(msmesh::threads(), initial);  // a refused value changes nothing
#ifdef _OPENMP
  set_threads(1);
  EXPECT_EQ(msmesh::threads(), 1);
  set_threads(3);
  EXPECT_EQ(msmesh::threads(), 3);
  set_threads(0);  // the default again
  EXPECT_EQ(msmesh::threads(), initial);
#else
  set_threads(3);
  EXPECT_EQ(msmesh::threads(), 1);
#endif
}
