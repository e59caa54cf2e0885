// vertex_update.h (Algorithm 2): a mesh that matches its target normals stays, the update
// moves vertices towards target normals, is invariant to scale and translation, pins nothing
// it should not, and refuses bad options, targets and weights; the fairness along the normals
// (τ < 1) keeps a flat mesh's triangles and still bends. Cholesky and CG agree:
// test_solver.cpp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "msmesh/vertex_update.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Denoise, VertexUpdateKeepsAMeshThatAlreadyMatchesItsNormals) {
  // With ω₂ = 0 the energy (24) is zero at V⁰ when the targets are V⁰'s own normals. (The
  // fairness term is not: it pulls edge-adjacent triangle pairs towards parallelograms.)
  const Mesh m = make_sphere(2);
  VertexUpdateOptions o;
  o.omega2 = 0;
  const VertexUpdateResult r = update_vertices(m.V, m.F, face_normals(m.V, m.F), {}, o);
  EXPECT_LT((r.V - m.V).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(VertexUpdate, MovesAFlatGridTowardsTiltedTargetNormals) {
  // Every target normal tilted the same way: the grid becomes a tilted plane (a rigid tilt of
  // the flat grid matches the targets exactly).
  const Mesh g = test::grid(8);
  const Eigen::RowVector3d target = Eigen::RowVector3d(0.3, 0, 1).normalized();
  const Eigen::MatrixXd N = target.replicate(g.F.rows(), 1);
  VertexUpdateOptions o;
  o.omega2 = 0;
  o.omega3 = 0.001;
  o.max_iterations = 100;
  const VertexUpdateResult r = update_vertices(g.V, g.F, N, {}, o);
  ASSERT_EQ(r.V.rows(), g.V.rows());
  EXPECT_TRUE(r.V.allFinite());
  const Eigen::MatrixXd n = face_normals(r.V, g.F);
  const double before = (face_normals(g.V, g.F) - N).rowwise().norm().maxCoeff();
  const double after = (n - N).rowwise().norm().maxCoeff();
  EXPECT_LT(after, 0.2 * before);
  EXPECT_GE(r.iterations, 1);
  EXPECT_EQ(r.change_history.size(), static_cast<size_t>(r.iterations));
}

TEST(VertexUpdate, InvariantUnderScaleAndTranslation) {
  const Mesh m = test::noisy_cube(4, 0.1);
  const Mesh c = make_cube(4);
  const Eigen::MatrixXd N = face_normals(c.V, c.F);
  const VertexUpdateResult a = update_vertices(m.V, m.F, N);
  const Eigen::RowVector3d shift(5, -2, 1);
  const Eigen::MatrixXd V2 = (7.0 * m.V).rowwise() + shift;
  const VertexUpdateResult b = update_vertices(V2, m.F, N);
  const Eigen::MatrixXd back = (b.V.rowwise() - shift) / 7.0;
  EXPECT_LT((back - a.V).cwiseAbs().maxCoeff(), 1e-8 * m.V.cwiseAbs().maxCoeff());
}

TEST(VertexUpdate, LargeOmega3MultiplierPinsAVertex) {
  const Mesh m = test::noisy_cube(4, 0.2);
  const Mesh c = make_cube(4);
  VertexUpdateWeights w;
  w.vertex_omega3 = Eigen::VectorXd::Ones(m.V.rows());
  w.vertex_omega3(0) = 1e9;
  const VertexUpdateResult r = update_vertices(m.V, m.F, face_normals(c.V, c.F), {}, {}, w);
  EXPECT_LT((r.V.row(0) - m.V.row(0)).norm(), 1e-5 * mean_edge_length(m.V, m.F));
  EXPECT_GT((r.V - m.V).rowwise().norm().maxCoeff(), 1e-3 * mean_edge_length(m.V, m.F));
}

TEST(VertexUpdate, RefusesBadOptionsTargetsAndWeights) {
  const Mesh m = test::grid(3);
  const Eigen::MatrixXd N = face_normals(m.V, m.F);
  VertexUpdateOptions bad;
  bad.omega3 = 0;
  EXPECT_THROW(bad.validate(), InvalidInput);
  EXPECT_THROW(update_vertices(m.V, m.F, N, {}, bad), InvalidInput);
  bad = {};
  bad.max_iterations = 0;
  EXPECT_THROW(update_vertices(m.V, m.F, N, {}, bad), InvalidInput);
  EXPECT_NO_THROW(VertexUpdateOptions{}.validate());
  EXPECT_THROW(update_vertices(m.V, m.F, N.topRows(2)), InvalidInput);
  EXPECT_THROW(update_vertices(m.V, m.F, N, Eigen::VectorXd::Ones(3)), InvalidInput);
  VertexUpdateWeights w;
  w.vertex_omega3 = Eigen::VectorXd::Ones(2);
  EXPECT_THROW(update_vertices(m.V, m.F, N, {}, {}, w), InvalidInput);
}

TEST(VertexUpdate, ProgressReportsEachIterationAndCanCancel) {
  const Mesh m = test::noisy_cube(3, 0.2);
  const Mesh c = make_cube(3);
  const Eigen::MatrixXd N = face_normals(c.V, c.F);
  VertexUpdateOptions o;
  o.tolerance = 0;
  o.max_iterations = 4;
  int calls = 0;
  update_vertices(m.V, m.F, N, {}, o, {}, [&](const ProgressEvent& e) {
    ++calls;
    EXPECT_EQ(e.stage, "vertex update");
    EXPECT_EQ(e.iteration, calls);
    EXPECT_EQ(e.max_iterations, 4);
    return true;
  });
  EXPECT_EQ(calls, 4);
  EXPECT_THROW(update_vertices(m.V, m.F, N, {}, o, {}, [](const ProgressEvent&) { return false; }), Cancelled);
}

TEST(VertexUpdate, AccelerationReachesThePlainAlternationsFixedPointInFewerSteps) {
  // Anderson acceleration changes the path, not the limit: both run to a tight tolerance end
  // at the same positions, the accelerated one in far fewer V-steps. Factored and CG alike.
  const Mesh m = test::noisy_cube(6, 0.15);
  const Mesh c = make_cube(6);
  const Eigen::MatrixXd N = face_normals(c.V, c.F);
  for (LinearSolver solver : {LinearSolver::Cholesky, LinearSolver::CG}) {
    VertexUpdateOptions plain;
    plain.acceleration = 0;
    plain.tolerance = 1e-9;
    plain.max_iterations = 2000;
    plain.solver = solver;
    plain.solver_tolerance = 1e-12;
    VertexUpdateOptions fast = plain;
    fast.acceleration = 5;
    const VertexUpdateResult a = update_vertices(m.V, m.F, N, {}, plain);
    const VertexUpdateResult b = update_vertices(m.V, m.F, N, {}, fast);
    ASSERT_TRUE(a.converged);
    ASSERT_TRUE(b.converged);
    EXPECT_LT((a.V - b.V).cwiseAbs().maxCoeff(), 1e-6 * m.V.cwiseAbs().maxCoeff());
    EXPECT_LT(2 * b.iterations, a.iterations) << "plain " << a.iterations << ", accelerated " << b.iterations;
  }
}

// A flat grid jittered within its plane, with targets (0, 0, 1): the normal term, the
// closeness and the fairness along the normals are all zero at the input, so τ = 0 keeps it;
// the whole fairness (τ = 1, the paper's) evens the triangles out and moves it.
TEST(VertexUpdate, FairnessAlongTheNormalsKeepsAFlatGridsTriangles) {
  Mesh g = test::grid(8);
  g.V.col(2).setZero();
  const Mesh jitter = test::noisy(g, 0.02);
  g.V.leftCols(2) = jitter.V.leftCols(2);
  const Eigen::MatrixXd N = Eigen::RowVector3d(0, 0, 1).replicate(g.F.rows(), 1);
  for (LinearSolver solver : {LinearSolver::Cholesky, LinearSolver::CG}) {
    VertexUpdateOptions o;
    o.solver = solver;
    o.solver_tolerance = 1e-12;
    o.fairness_tangential = 0;
    EXPECT_LT((update_vertices(g.V, g.F, N, {}, o).V - g.V).cwiseAbs().maxCoeff(), 1e-9);
    o.fairness_tangential = 1;
    EXPECT_GT((update_vertices(g.V, g.F, N, {}, o).V - g.V).cwiseAbs().maxCoeff(), 1e-3);
  }
}

// The fairness along the normals still bends: on a grid jittered within its plane, with a bump
// and flat targets, τ = 0 lowers the bump as τ = 1 does but leaves the jitter nearly in place,
// and τ = 0.5 moves the vertices along the plane less than τ = 1 and more than τ = 0. Its Q-step
// sees the targets only through each edge's plane, so the update stays invariant under
// rotation (targets rotated too), scale and translation.
TEST(VertexUpdate, FairnessAlongTheNormalsStillBendsAndIsInvariant) {
  Mesh g = test::grid(10, 0.05);
  const Mesh jitter = test::noisy(g, 0.02);
  g.V.leftCols(2) = jitter.V.leftCols(2);
  const Eigen::MatrixXd N = Eigen::RowVector3d(0, 0, 1).replicate(g.F.rows(), 1);
  VertexUpdateOptions o;
  o.omega2 = 1;
  o.max_iterations = 200;
  o.tolerance = 1e-9;
  const double before = test::z_rms(g.V, 0, g.V.rows());
  std::vector<double> bump, along;
  for (double tau : {0.0, 0.5, 1.0}) {
    o.fairness_tangential = tau;
    const Eigen::MatrixXd V = update_vertices(g.V, g.F, N, {}, o).V;
    bump.push_back(test::z_rms(V, 0, V.rows()));
    along.push_back((V.leftCols(2) - g.V.leftCols(2)).rowwise().norm().mean());
  }
  EXPECT_LT(bump[0], 0.6 * before);
  EXPECT_LT(bump[2], 0.6 * before);
  EXPECT_LT(along[0], 0.2 * along[2]) << along[0] << " " << along[2];
  EXPECT_LT(along[0], along[1]);
  EXPECT_LT(along[1], along[2]);

  const Mesh m = test::noisy_cube(4, 0.1);
  const Mesh c = make_cube(4);
  const Eigen::MatrixXd Nc = face_normals(c.V, c.F);
  VertexUpdateOptions half;
  half.fairness_tangential = 0.3;
  const VertexUpdateResult a = update_vertices(m.V, m.F, Nc, {}, half);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::RowVector3d shift(5, -2, 1);
  const Eigen::MatrixXd V2 = ((3.0 * m.V) * R.transpose()).rowwise() + shift;
  const VertexUpdateResult b = update_vertices(V2, m.F, Nc * R.transpose(), {}, half);
  const Eigen::MatrixXd back = ((b.V.rowwise() - shift) / 3.0) * R;
  EXPECT_LT((back - a.V).cwiseAbs().maxCoeff(), 1e-7 * m.V.cwiseAbs().maxCoeff());
  half.fairness_tangential = 1.5;
  EXPECT_THROW(half.validate(), InvalidInput);
  half.fairness_tangential = -0.1;
  EXPECT_THROW(update_vertices(m.V, m.F, Nc, {}, half), InvalidInput);
}

TEST(VertexUpdate, ThePaperPresetKeepsThePlainAlternation) {
  EXPECT_EQ(preset_options("paper").vertices.acceleration, 0);
  EXPECT_GT(preset_options("cad").vertices.acceleration, 0);
  EXPECT_EQ(inpaint_vertex_options().acceleration, 0);
}
