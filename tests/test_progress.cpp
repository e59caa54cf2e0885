// progress.h: the event's defaults, and the contract every long-running function keeps: one
// event per iteration with the stage named, iteration in [1, max_iterations], and a callback
// returning false stops the work with Cancelled (here with the normal filter; the other
// callers' stages: test_normal_filter.cpp, test_vertex_update.cpp, test_bilateral.cpp,
// test_multicut.cpp, test_segment.cpp, test_denoise.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/normal_filter.h"
#include "msmesh/progress.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Progress, EventDefaults) {
  const ProgressEvent e;
  EXPECT_TRUE(e.stage.empty());
  EXPECT_EQ(e.iteration, 0);
  EXPECT_EQ(e.max_iterations, 0);
  EXPECT_EQ(e.residual, 0.0);
  const ProgressCallback none;
  EXPECT_FALSE(none);  // an empty callback means "no progress reporting"
}

TEST(Progress, IterationsCountUpWithinTheirMaximumAndFalseCancels) {
  const Mesh m = test::noisy_cube(3, 0.2);
  NormalFilterOptions o;
  o.tolerance = 0;
  o.max_iterations = 5;
  std::set<std::string> stages;
  int last = 0;
  filter_normals(m.V, m.F, o, {}, [&](const ProgressEvent& e) {
    stages.insert(e.stage);
    EXPECT_EQ(e.iteration, last + 1);
    EXPECT_GE(e.iteration, 1);
    EXPECT_LE(e.iteration, e.max_iterations);
    EXPECT_TRUE(std::isfinite(e.residual));
    last = e.iteration;
    return true;
  });
  EXPECT_EQ(last, 5);
  EXPECT_EQ(stages, std::set<std::string>{"normal filtering"});
  // Cancelling after the second event: the work stops there.
  int calls = 0;
  EXPECT_THROW(filter_normals(m.V, m.F, o, {}, [&](const ProgressEvent&) { return ++calls < 2; }), Cancelled);
  EXPECT_EQ(calls, 2);
}
