// The vertex update run again with new targets on the system it built (src/retargeted_update.h):
// without new targets it is update_vertices; with the same targets the second run stops at once
// near the first's result (the closeness still pulls towards the input); with better targets
// the result follows them, with the fairness along the surface or along the normals (whose
// system reads the targets and is built again); both runs are counted in the report.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "msmesh/geometry.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/shapes.h"
#include "msmesh/vertex_update.h"
#include "retargeted_update.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(InternalRetargetedUpdate, WithoutNewTargetsItIsTheUpdate) {
  const Mesh m = test::noisy_cube(5, 0.2);
  const Mesh c = make_cube(5);
  const PreparedMesh mesh(m.V, m.F);
  const Eigen::MatrixXd N = face_normals(c.V, c.F);
  const VertexUpdateResult plain = update_vertices(mesh, N, {});
  int calls = 0;
  const VertexUpdateResult same =
      detail::update_vertices_retargeted(mesh, N, {}, {}, {}, {}, [&](const Eigen::MatrixXd& X, Eigen::MatrixXd&) {
        ++calls;
        // the positions it reached, in the prepared mesh's units
        EXPECT_LT((mesh.to_input_units(X) - plain.V).cwiseAbs().maxCoeff(), 1e-12);
        return false;
      });
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(same.V, plain.V);
  EXPECT_EQ(same.iterations, plain.iterations);
  EXPECT_EQ(same.change_history, plain.change_history);
}

TEST(InternalRetargetedUpdate, TheSameTargetsAgainStopAtOnceNearTheFirstResult) {
  const Mesh m = test::noisy_cube(5, 0.2);
  const Mesh c = make_cube(5);
  const PreparedMesh mesh(m.V, m.F);
  const Eigen::MatrixXd N = face_normals(c.V, c.F);
  VertexUpdateOptions o;
  o.tolerance = 1e-6;
  o.max_iterations = 200;
  const VertexUpdateResult first = update_vertices(mesh, N, {}, o);
  ASSERT_TRUE(first.converged);
  EXPECT_GT(first.iterations, 2);
  const VertexUpdateResult again =
      detail::update_vertices_retargeted(mesh, N, {}, o, {}, {}, [](const Eigen::MatrixXd&, Eigen::MatrixXd&) {
        return true;  // "changed": the same targets run again
      });
  EXPECT_TRUE(again.converged);
  EXPECT_LE(again.iterations - first.iterations, 2);
  EXPECT_EQ(again.change_history.size(), static_cast<std::size_t>(again.iterations));
  EXPECT_LT((again.V - first.V).cwiseAbs().maxCoeff(), 1e-4 * mean_edge_length(m.V, m.F));
}

TEST(InternalRetargetedUpdate, NewTargetsAreFollowedAlongTheSurfaceOrAlongTheNormals) {
  // First targets: the noisy cube's own normals (nothing to do); new ones: the cube's. The
  // result then matches the cube's normals far better than the first run's, for τ = 1 (same
  // system) and τ = 0 (the system built again from the new targets).
  const Mesh m = test::noisy_cube(6, 0.15);
  const Mesh c = make_cube(6);
  const PreparedMesh mesh(m.V, m.F);
  const Eigen::MatrixXd noisy = face_normals(m.V, m.F), truth = face_normals(c.V, c.F);
  for (const double tau : {1.0, 0.0}) {
    VertexUpdateOptions o;
    o.fairness_tangential = tau;
    const VertexUpdateResult first = update_vertices(mesh, noisy, {}, o);
    const VertexUpdateResult both =
        detail::update_vertices_retargeted(mesh, noisy, {}, o, {}, {}, [&](const Eigen::MatrixXd&, Eigen::MatrixXd& N) {
          N = truth;
          return true;
        });
    EXPECT_GT(both.iterations, first.iterations) << tau;
    EXPECT_EQ(both.change_history.size(), static_cast<std::size_t>(both.iterations)) << tau;
    const double before = test::mean_squared_angle(face_normals(first.V, m.F), truth);
    const double after = test::mean_squared_angle(face_normals(both.V, m.F), truth);
    EXPECT_LT(after, 0.2 * before) << tau << ": " << before << " -> " << after;
  }
}
