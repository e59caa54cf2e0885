// `msmesh --threads N`. The library's set_threads: test_threads.cpp.
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;

// msmesh --threads N, before or after the subcommand: the JSON says how many threads ran, the
// output is the same bytes for one and two threads, and a bad value is refused.
TEST(Threads, CommandLineOption) {
  test::TempDir dir;
  const std::string in = dir.file("in.obj"), a = dir.file("a.ply"), b = dir.file("b.ply");
  const Mesh m = test::noisy_cube(6);
  write_mesh(in, m);
  const test::CliRun one = test::run_cli("--threads 1 denoise '" + in + "' -o '" + a + "' --preset cad --json");
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_NE(one.out.find("\"threads\":1"), std::string::npos) << one.out;
  const test::CliRun two = test::run_cli("denoise '" + in + "' -o '" + b + "' --preset cad --json --threads 2");
  ASSERT_EQ(two.status, 0) << two.out;
#ifdef _OPENMP
  EXPECT_NE(two.out.find("\"threads\":2"), std::string::npos) << two.out;
#endif
  EXPECT_EQ(test::read_bytes(a), test::read_bytes(b));
  EXPECT_FALSE(test::read_bytes(a).empty());
  for (const char* bad : {"0", "-2", "many"}) {
    const test::CliRun r = test::run_cli(std::string("--threads ") + bad + " info '" + in + "'");
    EXPECT_NE(r.status, 0) << bad;
    EXPECT_NE(r.out.find("--threads"), std::string::npos) << r.out;
  }
}
