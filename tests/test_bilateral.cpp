// bilateral.h: the bilateral normal filtering baseline (Zheng et al. 2011) and the classic
// vertex update (Sun et al. 2007) called directly: unit normals closer to the clean ones, a
// flat grid kept flat, vertices moved to match target normals, refusals and cancelling. Through
// denoise(): test_denoise.cpp (Denoise.BilateralBaselineDenoises).
#include <gtest/gtest.h>

#include "msmesh/bilateral.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/shapes.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Bilateral, FilteredNormalsAreUnitAndCloserToTheCleanOnes) {
  const Mesh m = test::noisy_cube(6, 0.2);
  const Mesh c = make_cube(6);
  const Eigen::MatrixXd N = bilateral_filter_normals(m.V, m.F, BilateralOptions{});
  ASSERT_EQ(N.rows(), m.F.rows());
  ASSERT_EQ(N.cols(), 3);
  for (Eigen::Index f = 0; f < N.rows(); ++f) EXPECT_NEAR(N.row(f).norm(), 1.0, 1e-9);
  const Eigen::MatrixXd clean = face_normals(c.V, c.F);
  EXPECT_LT((N - clean).norm(), 0.5 * (face_normals(m.V, m.F) - clean).norm());
}

TEST(Bilateral, FlatGridStaysFlat) {
  const Mesh g = test::grid(5);
  const Eigen::MatrixXd N = bilateral_filter_normals(g.V, g.F, BilateralOptions{});
  for (Eigen::Index f = 0; f < N.rows(); ++f) EXPECT_TRUE(N.row(f).isApprox(Eigen::RowVector3d(0, 0, 1), 1e-9));
  const Eigen::MatrixXd V = classic_vertex_update(g.V, g.F, N, 10);
  EXPECT_LT((V - g.V).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Bilateral, ClassicVertexUpdateMovesTowardsTheTargetNormals) {
  const Mesh m = test::noisy_cube(5, 0.2);
  const Mesh c = make_cube(5);
  const Eigen::MatrixXd clean = face_normals(c.V, c.F);
  const Eigen::MatrixXd V = classic_vertex_update(m.V, m.F, clean, 20);
  ASSERT_EQ(V.rows(), m.V.rows());
  EXPECT_LT((face_normals(V, m.F) - clean).norm(), 0.5 * (face_normals(m.V, m.F) - clean).norm());
}

TEST(Bilateral, RefusesBadOptionsAndTargetsAndCanCancel) {
  const Mesh g = test::grid(3);
  BilateralOptions o;
  EXPECT_NO_THROW(o.validate());
  o.sigma_r = 3;
  EXPECT_THROW(o.validate(), InvalidInput);
  EXPECT_THROW(bilateral_filter_normals(g.V, g.F, o), InvalidInput);
  o = {};
  o.normal_iterations = 0;
  EXPECT_THROW(bilateral_filter_normals(g.V, g.F, o), InvalidInput);
  EXPECT_THROW(classic_vertex_update(g.V, g.F, Eigen::MatrixXd::Zero(2, 3), 5), InvalidInput);
  int calls = 0;
  bilateral_filter_normals(g.V, g.F, BilateralOptions{}, [&](const ProgressEvent& e) {
    EXPECT_EQ(e.stage, "bilateral normals");
    EXPECT_EQ(e.iteration, ++calls);
    return true;
  });
  EXPECT_EQ(calls, BilateralOptions{}.normal_iterations);
  EXPECT_THROW(bilateral_filter_normals(g.V, g.F, BilateralOptions{}, [](const ProgressEvent&) { return false; }),
               Cancelled);
  const Eigen::MatrixXd N = face_normals(g.V, g.F);
  EXPECT_THROW(classic_vertex_update(g.V, g.F, N, 3, [](const ProgressEvent&) { return false; }), Cancelled);
}
