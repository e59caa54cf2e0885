// Unreachable targets (src/unreachable_targets.h): a face whose target its neighbours keep it
// from ends far from it; it is marked (and only what ends far from its target is), the mark
// turns with the mesh and ignores its scale and position; with its target dropped the second
// update brings the face back among its neighbours; and through denoise() a noisy fandisk, where
// Algorithm 1 gives faces beside creases the other side's normal, gains, with the options and
// presets that turn it off.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "msmesh/vertex_update.h"
#include "retargeted_update.h"
#include "test_helpers.h"
#include "unreachable_targets.h"

using namespace msmesh;

namespace {

double angle_deg(const Eigen::RowVector3d& a, const Eigen::RowVector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI;
}

// n turned by `deg` degrees about an axis orthogonal to it.
Eigen::RowVector3d tilted(const Eigen::RowVector3d& n, double deg) {
  const Eigen::Vector3d u = n.transpose();
  const Eigen::Vector3d axis = u.cross(std::abs(u.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY());
  return (Eigen::AngleAxisd(deg * M_PI / 180, axis.normalized()) * u).transpose();
}

}  // namespace

TEST(InternalUnreachableTargets, AFaceItsNeighboursHoldIsMarkedAndFollowsThemOnceDropped) {
  // A face inside a side of a noisy cube given a target 60° off: its neighbours hold it near
  // their plane, far from that target. Marked after the update, its target dropped, the second
  // update brings it back among its neighbours.
  const Mesh cube = make_cube(6);
  const Mesh noisy = test::noisy_cube(6, 0.2);
  const PreparedMesh mesh(noisy.V, noisy.F);
  const Eigen::MatrixXd truth = face_normals(cube.V, cube.F);
  const Topology& topo = mesh.topology();
  Eigen::Index bad = -1;  // a face whose edge neighbours all lie on its side
  for (Eigen::Index f = 0; f < cube.F.rows() && bad < 0; ++f) {
    bool inside = true;
    for (int k = 0; k < 3; ++k)
      for (int s = 0; s < 2; ++s) {
        const Eigen::Index g = topo.edge_faces(topo.face_edges(f, k), s);
        inside = inside && g >= 0 && truth.row(g).dot(truth.row(f)) > 0.99;
      }
    if (inside) bad = f;
  }
  ASSERT_GE(bad, 0);
  Eigen::MatrixXd N = truth;
  N.row(bad) = tilted(truth.row(bad), 60);
  // The edge field Algorithm 1 would give: 0 on the creases (no fairness across them), 1 elsewhere.
  Eigen::VectorXd v = Eigen::VectorXd::Ones(topo.edges.rows());
  for (Eigen::Index e = 0; e < topo.edges.rows(); ++e)
    if (topo.edge_faces(e, 1) >= 0 && truth.row(topo.edge_faces(e, 0)).dot(truth.row(topo.edge_faces(e, 1))) < 0.5)
      v(e) = 0;
  VertexUpdateOptions o;  // run to their fixed points
  o.tolerance = 1e-8;
  o.max_iterations = 1000;
  const auto error_deg = [&](const VertexUpdateResult& r) {
    return angle_deg(face_normals(r.V, cube.F).row(bad), truth.row(bad));
  };
  const VertexUpdateResult right = update_vertices(mesh, truth, v, o);
  const VertexUpdateResult held = update_vertices(mesh, N, v, o);
  EXPECT_GT(angle_deg(face_normals(held.V, cube.F).row(bad), N.row(bad)), 30.0);  // far from its target
  EXPECT_GT(error_deg(held), 3 * error_deg(right));                               // but pulled off its side

  detail::UnreachableTargets found;
  const VertexUpdateResult freed = detail::update_vertices_retargeted(
      mesh, N, v, o, {}, {}, [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& targets) {
        found = detail::unreachable_targets(X, mesh.faces(), targets, 10.0);
        detail::drop_targets(found.marked, targets);
        return found.faces > 0;
      });
  ASSERT_EQ(found.marked.size(), static_cast<std::size_t>(cube.F.rows()));
  EXPECT_TRUE(found.marked[static_cast<std::size_t>(bad)]);
  EXPECT_LE(found.faces, 4);  // it, and a neighbour or two it dragged along
  // (right 0.34°, held 10.9°, freed 1.0°: with no target of its own it is held only by its
  // neighbours and the closeness to the noisy input)
  EXPECT_LT(error_deg(freed), 0.15 * error_deg(held)) << error_deg(right) << " " << error_deg(held);
}

TEST(InternalUnreachableTargets, MarksOnlyFacesFarFromTheirTargetsWhateverTheFrame) {
  const Mesh cube = make_cube(4);
  const Eigen::MatrixXd truth = face_normals(cube.V, cube.F);
  Eigen::MatrixXd N = truth;
  N.row(7) = tilted(truth.row(7), 15);  // 15° off
  N.row(20) = tilted(truth.row(20), 5);
  const std::vector<char> mask = detail::unreachable_targets(cube.V, cube.F, N, 10.0).marked;
  EXPECT_EQ(detail::unreachable_targets(cube.V, cube.F, N, 10.0).faces, 1);
  EXPECT_TRUE(mask[7]);
  EXPECT_EQ(std::count(mask.begin(), mask.end(), 1), 1);
  EXPECT_EQ(detail::unreachable_targets(cube.V, cube.F, N, 4.0).faces, 2);
  EXPECT_EQ(detail::unreachable_targets(cube.V, cube.F, N, 0.0).faces, 0);  // off

  // Rotated, scaled and moved together with its targets: the same faces.
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::MatrixXd moved = ((cube.V * R.transpose()) * 37.0).rowwise() + Eigen::RowVector3d(5, -3, 11);
  const detail::UnreachableTargets in_moved = detail::unreachable_targets(moved, cube.F, N * R.transpose(), 10.0);
  EXPECT_EQ(in_moved.marked, mask);
  EXPECT_EQ(in_moved.faces, 1);

  Eigen::MatrixXd dropped = N;
  detail::drop_targets(mask, dropped);
  EXPECT_EQ(dropped.row(7).squaredNorm(), 0.0);
  dropped.row(7) = N.row(7);
  EXPECT_EQ(dropped, N);  // nothing else touched
}

TEST(InternalUnreachableTargets, DenoisingANoisyFandiskGains) {
  // Through denoise(): preset cad with its unreachable targets dropped against kept, on the
  // procedural fandisk with σ 0.3 mean edges along the normals, where Algorithm 1 puts faces
  // beside its creases on the wrong side; and the presets and options that turn it off.
  const Mesh fandisk = make_shape("fandisk", 16);
  NoiseOptions no;
  no.sigma = 0.3;
  no.seed = 3;
  const Eigen::MatrixXd noisy = add_noise(fandisk.V, fandisk.F, no);
  DenoiseOptions with = preset_options("cad"), without = with;
  EXPECT_EQ(with.unreachable_angle, 10.0);
  without.unreachable_angle = 0;
  const DenoiseResult a = denoise(noisy, fandisk.F, without), b = denoise(noisy, fandisk.F, with);
  EXPECT_EQ(a.unreachable_faces, 0);
  EXPECT_GT(b.unreachable_faces, 0);
  EXPECT_LT(b.unreachable_faces, fandisk.F.rows() / 50);
  const double e_without = normal_errors(a.V, fandisk.F, fandisk.V, fandisk.F).msae;
  const double e_with = normal_errors(b.V, fandisk.F, fandisk.V, fandisk.F).msae;
  EXPECT_LT(e_with, 0.85 * e_without) << e_without << " -> " << e_with;
  // The reported targets stay unit normals (a dropped one: the normal its face ended with).
  EXPECT_LT((b.normals.rowwise().norm().array() - 1).abs().maxCoeff(), 1e-9);
  EXPECT_EQ(preset_options("smooth").unreachable_angle, 0.0);
  EXPECT_EQ(preset_options("paper").unreachable_angle, 0.0);
  EXPECT_EQ(denoise(noisy, fandisk.F, preset_options("paper")).unreachable_faces, 0);
  DenoiseOptions bad;
  bad.unreachable_angle = -1;
  EXPECT_THROW(denoise(noisy, fandisk.F, bad), InvalidInput);
  bad.unreachable_angle = 181;
  EXPECT_THROW(denoise(noisy, fandisk.F, bad), InvalidInput);
  bad.unreachable_angle = std::nan("");
  EXPECT_THROW(denoise(noisy, fandisk.F, bad), InvalidInput);
}
