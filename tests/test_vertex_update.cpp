// vertex_update.h (Algorithm 2): a mesh that matches its target normals stays, the update
// moves vertices towards target normals, is invariant to scale and translation, pins nothing
// it should not, and refuses bad options, targets and weights. Cholesky and CG agree:
// test_solver.cpp.
#include <gtest/gtest.h>

#include <string>

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

TEST(VertexUpdate, ThePaperPresetKeepsThePlainAlternation) {
  EXPECT_EQ(preset_options("paper").vertices.acceleration, 0);
  EXPECT_GT(preset_options("cad").vertices.acceleration, 0);
  EXPECT_EQ(inpaint_vertex_options().acceleration, 0);
}
