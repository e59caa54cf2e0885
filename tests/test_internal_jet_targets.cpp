// Jet-fitted targets (src/jet_targets.h): on a curved surface a quadric through the vertices
// gives each face the normal of the smooth surface where Algorithm 1's plateaus give a facet's;
// flat plateaus, creases and fixed faces are left alone; the result turns with the mesh and
// does not depend on its scale or position; and through denoise() a noisy torus gains.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "jet_targets.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

// Plateaus: every normal replaced by the nearest of the directions whose polar and azimuthal
// angles are multiples of `step_deg` (the piecewise constant normals of a staircased surface).
Eigen::MatrixXd plateaus(const Eigen::MatrixXd& N, double step_deg) {
  const double step = step_deg * M_PI / 180;
  Eigen::MatrixXd out(N.rows(), 3);
  for (Eigen::Index f = 0; f < N.rows(); ++f) {
    const double theta = std::round(std::acos(std::clamp(N(f, 2), -1.0, 1.0)) / step) * step;
    const double phi = std::round(std::atan2(N(f, 1), N(f, 0)) / step) * step;
    out.row(f) << std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta);
  }
  return out;
}

// The positions normalised as PreparedMesh does (mean edge 1, vertex mean at the origin).
Eigen::MatrixXd normalised(const PreparedMesh& mesh, const Eigen::MatrixXd& V) {
  return (V.rowwise() - mesh.center()) / mesh.scale();
}

}  // namespace

TEST(InternalJetTargets, CurvedSurfacesGetTheirSmoothNormalsBack) {
  // A fine torus (curvature everywhere, 1.2° between neighbouring faces) with exact positions
  // and plateau targets 6° apart: the quadrics' normals are much nearer the true ones.
  const Mesh torus = make_shape("torus", 30);
  const Eigen::MatrixXd truth = face_normals(torus.V, torus.F);
  const PreparedMesh mesh(torus.V, torus.F);
  Eigen::MatrixXd N = plateaus(truth, 6.0);
  const double before = test::mean_squared_angle(N, truth);
  const detail::JetTargets r = detail::fit_jet_targets(mesh, normalised(mesh, torus.V), N, 3, {});
  EXPECT_GT(r.faces, torus.F.rows() / 2);
  const double after = test::mean_squared_angle(N, truth);
  EXPECT_LT(after, 0.2 * before) << before << " -> " << after;
  for (Eigen::Index f = 0; f < N.rows(); ++f) ASSERT_NEAR(N.row(f).norm(), 1.0, 1e-12);
}

TEST(InternalJetTargets, FlatPlateausCreasesAndFixedFacesAreLeftAlone) {
  // A cube with its exact normals: every neighbourhood stops at the 90° creases and is flat
  // (all within kJetFlatDeg), so nothing changes; rings 0 changes nothing either.
  const Mesh cube = make_cube(8);
  const PreparedMesh mesh(cube.V, cube.F);
  const Eigen::MatrixXd X = normalised(mesh, cube.V);
  const Eigen::MatrixXd exact = face_normals(cube.V, cube.F);
  Eigen::MatrixXd N = exact;
  EXPECT_EQ(detail::fit_jet_targets(mesh, X, N, 3, {}).faces, 0);
  EXPECT_EQ(N, exact);
  // Faces marked fixed keep their targets even where a fit would change them.
  const Mesh torus = make_shape("torus", 30);
  const PreparedMesh round(torus.V, torus.F);
  const Eigen::MatrixXd N0 = plateaus(face_normals(torus.V, torus.F), 6.0);
  std::vector<bool> fixed(static_cast<std::size_t>(torus.F.rows()), false);
  for (std::size_t f = 0; f < fixed.size(); f += 2) fixed[f] = true;
  Eigen::MatrixXd Nt = N0;
  const detail::JetTargets r = detail::fit_jet_targets(round, normalised(round, torus.V), Nt, 3, fixed);
  EXPECT_GT(r.faces, 0);
  for (std::size_t f = 0; f < fixed.size(); f += 2)
    EXPECT_EQ(Nt.row(static_cast<Eigen::Index>(f)), N0.row(static_cast<Eigen::Index>(f)));
  Eigen::MatrixXd Nz = N0;
  EXPECT_EQ(detail::fit_jet_targets(round, normalised(round, torus.V), Nz, 0, {}).faces, 0);
  EXPECT_EQ(Nz, N0);
}

TEST(InternalJetTargets, DetailAQuadricCannotFollowKeepsItsTargets) {
  // The same torus with its vertices displaced by ~0.2 mean edges (more than kJetMaxResidual):
  // the fits leave that residual, and (almost) every face keeps its target.
  const Mesh torus = make_shape("torus", 30);
  const Eigen::MatrixXd N0 = plateaus(face_normals(torus.V, torus.F), 6.0);
  const PreparedMesh smooth(torus.V, torus.F);
  Eigen::MatrixXd N = N0;
  EXPECT_GT(detail::fit_jet_targets(smooth, normalised(smooth, torus.V), N, 3, {}).faces, torus.F.rows() / 2);
  NoiseOptions no;
  no.sigma = 0.2;
  no.seed = 3;
  const Eigen::MatrixXd bumpy = add_noise(torus.V, torus.F, no);
  const PreparedMesh mesh(bumpy, torus.F);
  N = N0;
  EXPECT_LT(detail::fit_jet_targets(mesh, normalised(mesh, bumpy), N, 3, {}).faces, torus.F.rows() / 100);
}

TEST(InternalJetTargets, TurnsWithTheMeshAndIgnoresScaleAndPosition) {
  const Mesh torus = make_shape("torus", 10);
  const Eigen::MatrixXd N0 = plateaus(face_normals(torus.V, torus.F), 6.0);
  const PreparedMesh mesh(torus.V, torus.F);
  Eigen::MatrixXd N = N0;
  const detail::JetTargets r = detail::fit_jet_targets(mesh, normalised(mesh, torus.V), N, 3, {});
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::MatrixXd moved = ((torus.V * R.transpose()) * 37.0).rowwise() + Eigen::RowVector3d(5, -3, 100);
  const PreparedMesh moved_mesh(moved, torus.F);
  Eigen::MatrixXd Nm = N0 * R.transpose();
  const detail::JetTargets rm = detail::fit_jet_targets(moved_mesh, normalised(moved_mesh, moved), Nm, 3, {});
  EXPECT_EQ(rm.faces, r.faces);
  EXPECT_LT(((N * R.transpose()) - Nm).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(InternalJetTargets, DenoisingANoisyTorusGains) {
  // Through denoise(): the defaults' jet-fitted targets against none on a noisy torus (σ 0.1
  // mean edges, along the normals), and the options that turn them off.
  const Mesh torus = make_shape("torus", 12);
  NoiseOptions no;
  no.sigma = 0.1;
  no.seed = 5;
  const Eigen::MatrixXd noisy = add_noise(torus.V, torus.F, no);
  DenoiseOptions with = preset_options("cad"), without = with;
  without.jet_rings = 0;
  const DenoiseResult a = denoise(noisy, torus.F, without), b = denoise(noisy, torus.F, with);
  EXPECT_EQ(a.jet_faces, 0);
  EXPECT_GT(b.jet_faces, torus.F.rows() / 2);
  EXPECT_GT(b.vertex_report.iterations, a.vertex_report.iterations);  // both updates counted
  EXPECT_EQ(b.vertex_report.change_history.size(), static_cast<std::size_t>(b.vertex_report.iterations));
  const double e_without = normal_errors(a.V, torus.F, torus.V, torus.F).msae;
  const double e_with = normal_errors(b.V, torus.F, torus.V, torus.F).msae;
  EXPECT_LT(e_with, 0.8 * e_without) << e_without << " -> " << e_with;
  EXPECT_EQ(preset_options("paper").jet_rings, 0);
  EXPECT_EQ(denoise(noisy, torus.F, preset_options("paper")).jet_faces, 0);
  DenoiseOptions bad;
  bad.jet_rings = -1;
  EXPECT_THROW(denoise(noisy, torus.F, bad), InvalidInput);
  bad.jet_rings = 11;
  EXPECT_THROW(denoise(noisy, torus.F, bad), InvalidInput);
}
