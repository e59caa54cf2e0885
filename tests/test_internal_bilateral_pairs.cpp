// bilateral_pairs.h (internal): the shape rule's pre-smoothing, weights computed once per pair
// of faces, gives the normals of bilateral_filter_normals (sigma_s 0) to single precision (its
// range weights are floats), on a mesh with creases, noise and a boundary, and on one with a
// component of its own.
#include <gtest/gtest.h>

#include "bilateral_pairs.h"
#include "msmesh/bilateral.h"
#include "msmesh/shapes.h"
#include "msmesh/threads.h"
#include "test_helpers.h"
#include "wide_rows.h"

using namespace msmesh;

namespace {

void expect_same_normals(const Mesh& m, int passes) {
  BilateralOptions o;
  o.normal_iterations = passes;
  const Eigen::MatrixXd reference = bilateral_filter_normals(m.V, m.F, o);
  const Eigen::MatrixXd by_pairs = detail::bilateral_normals_by_pairs(m.V, m.F, passes, o.sigma_r);
  ASSERT_EQ(by_pairs.rows(), m.F.rows());
  ASSERT_EQ(by_pairs.cols(), 3);
  EXPECT_LT((by_pairs - reference).cwiseAbs().maxCoeff(), 1e-6);
  // and the pre-smoothing really moved the normals (the comparison is not of two copies of N⁰)
  BilateralOptions one;
  one.normal_iterations = 1;
  if (passes > 1) EXPECT_GT((by_pairs - bilateral_filter_normals(m.V, m.F, one)).cwiseAbs().maxCoeff(), 1e-6);
}

}  // namespace

TEST(BilateralPairs, SameNormalsAsTheBilateralFilter) {
  expect_same_normals(test::noisy_cube(6, 0.2), 15);
  expect_same_normals(test::noisy(make_shape("fandisk", 8), 0.3), 15);
  expect_same_normals(test::noisy(test::grid(6, 0.3), 0.1), 3);  // a boundary
  expect_same_normals(test::join(test::noisy_cube(3), test::tetrahedron(), Eigen::RowVector3d(5, 0, 0)), 15);
}

TEST(BilateralPairs, SameBitsAtEveryThreadCount) {
  // 19200 faces: the neighbour lists, the pairs and the weights are built in parallel blocks.
  const Mesh cube = test::noisy_cube(40, 0.3);
  const int before = threads();
  set_threads(1);
  const Eigen::MatrixXd one = detail::bilateral_normals_by_pairs(cube.V, cube.F, 4, 0.35);
  for (const int n : {2, 3}) {
    SCOPED_TRACE(n);
    set_threads(n);
    EXPECT_TRUE(detail::bilateral_normals_by_pairs(cube.V, cube.F, 4, 0.35) == one);
  }
  set_threads(before);
  expect_same_normals(cube, 4);
}

TEST(BilateralPairs, WideRowsGiveTheScalarLoopsBits) {
  // The sums of each pass four entries at a time where the processor has AVX (wide_rows.h):
  // the same normals to the last bit as the scalar loop, on a mesh of several blocks.
  if (!detail::wide_rows()) GTEST_SKIP() << "no AVX on this processor: only the scalar loop runs";
  const Mesh m = test::noisy(make_shape("fandisk", 40), 0.3);
  ASSERT_GT(m.F.rows(), 8192);  // the passes' parallel loop
  const Eigen::MatrixXd wide = detail::bilateral_normals_by_pairs(m.V, m.F, 15, 0.35);
  detail::set_wide_rows(false);
  const Eigen::MatrixXd scalar = detail::bilateral_normals_by_pairs(m.V, m.F, 15, 0.35);
  detail::set_wide_rows(true);
  EXPECT_TRUE(test::bit_identical(wide, scalar));
}
