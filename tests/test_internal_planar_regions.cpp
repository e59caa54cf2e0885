// Planar regions of the filtered normals (src/planar_regions.h): the six sides of a noisy cube
// snap to their planes, curved surfaces and small regions are left alone, and the result
// turns with the mesh and does not depend on its scale or position.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "planar_regions.h"

using namespace msmesh;

namespace {

// Each unit normal turned by a random angle below `max_deg` (seeded).
Eigen::MatrixXd tilted(const Eigen::MatrixXd& N, double max_deg, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd out = N;
  for (Eigen::Index f = 0; f < N.rows(); ++f) {
    const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const double angle = std::abs(u(rng)) * max_deg * M_PI / 180;
    out.row(f) = (Eigen::AngleAxisd(angle, axis) * N.row(f).transpose()).transpose();
  }
  return out;
}

double largest_angle_deg(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  double worst = 0;
  for (Eigen::Index f = 0; f < A.rows(); ++f)
    worst = std::max(worst, std::acos(std::clamp(A.row(f).dot(B.row(f)), -1.0, 1.0)));
  return worst * 180 / M_PI;
}

struct NoisyCube {
  Mesh clean;
  Eigen::MatrixXd noisy;
};

NoisyCube noisy_cube(int n, double sigma) {
  NoisyCube c;
  c.clean = make_cube(n);
  NoiseOptions no;
  no.sigma = sigma;
  no.seed = 11;
  c.noisy = add_noise(c.clean.V, c.clean.F, no);
  return c;
}

}  // namespace

TEST(InternalPlanarRegions, NoisyCubeSidesSnapToTheirPlanes) {
  // Normals within 0.3° of the true ones (neighbours within 0.6° < 1°): each side is one
  // region (the 90° creases part them), fitted through the noisy vertices (σ 0.2 edges: a
  // plane through a side's 169 vertices 12 edges across tilts by ~0.25°; the faces' own
  // normals are ~10° off).
  const NoisyCube c = noisy_cube(12, 0.2);
  const Eigen::MatrixXd truth = face_normals(c.clean.V, c.clean.F);
  const PreparedMesh mesh(c.noisy, c.clean.F);
  Eigen::MatrixXd N = tilted(truth, 0.3, 5);
  const detail::PlanarRegions r = detail::snap_planar_regions(mesh, N, 100);
  EXPECT_EQ(r.regions, 6);
  EXPECT_EQ(r.faces, c.clean.F.rows());
  EXPECT_LT(largest_angle_deg(N, truth), 1.0);
  // Each side one normal.
  for (Eigen::Index f = 1; f < N.rows(); ++f)
    if (truth.row(f).dot(truth.row(0)) > 0.999) EXPECT_LT((N.row(f) - N.row(0)).norm(), 1e-12);
}

TEST(InternalPlanarRegions, RegionsBelowTheSizeOrSpreadAreLeftAlone) {
  const NoisyCube c = noisy_cube(6, 0.2);  // 72 faces a side
  const Eigen::MatrixXd truth = face_normals(c.clean.V, c.clean.F);
  const PreparedMesh mesh(c.noisy, c.clean.F);
  const Eigen::MatrixXd N0 = tilted(truth, 0.3, 7);
  for (const int min_faces : {0, -1, 73}) {
    Eigen::MatrixXd N = N0;
    const detail::PlanarRegions r = detail::snap_planar_regions(mesh, N, min_faces);
    EXPECT_EQ(r.regions, 0) << min_faces;
    EXPECT_EQ(N, N0) << min_faces;
  }
  Eigen::MatrixXd N = N0;
  EXPECT_EQ(detail::snap_planar_regions(mesh, N, 72).regions, 6);
  // A smooth sphere: neighbouring normals agree within 1°, but no region of 100 faces stays
  // within 4° of its mean.
  const Mesh sphere = make_shape("sphere", 32);
  const PreparedMesh round(sphere.V, sphere.F);
  const Eigen::MatrixXd Ns0 = face_normals(sphere.V, sphere.F);
  Eigen::MatrixXd Ns = Ns0;
  EXPECT_EQ(detail::snap_planar_regions(round, Ns, 100).regions, 0);
  EXPECT_EQ(Ns, Ns0);
}

TEST(InternalPlanarRegions, TurnsWithTheMeshAndIgnoresScaleAndPosition) {
  const NoisyCube c = noisy_cube(10, 0.2);
  const Eigen::MatrixXd truth = face_normals(c.clean.V, c.clean.F);
  const Eigen::MatrixXd N0 = tilted(truth, 0.3, 9);
  Eigen::MatrixXd N = N0;
  const detail::PlanarRegions r = detail::snap_planar_regions(PreparedMesh(c.noisy, c.clean.F), N, 100);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::MatrixXd moved = ((c.noisy * R.transpose()) * 37.0).rowwise() + Eigen::RowVector3d(5, -3, 100);
  Eigen::MatrixXd Nm = N0 * R.transpose();
  const detail::PlanarRegions rm = detail::snap_planar_regions(PreparedMesh(moved, c.clean.F), Nm, 100);
  EXPECT_EQ(rm.regions, r.regions);
  EXPECT_EQ(rm.faces, r.faces);
  EXPECT_LT(((N * R.transpose()) - Nm).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(InternalPlanarRegions, DenoisingANoisyCubeGains) {
  // Through denoise(): the defaults' planar regions against none, on a cube whose sides are
  // 2 · 14² faces.
  const NoisyCube c = noisy_cube(14, 0.3);
  DenoiseOptions with = preset_options("cad"), without = with;
  without.plane_min_faces = 0;
  const DenoiseResult a = denoise(c.noisy, c.clean.F, without), b = denoise(c.noisy, c.clean.F, with);
  EXPECT_EQ(a.planar_regions, 0);
  EXPECT_GE(b.planar_regions, 1);
  const double e_without = normal_errors(a.V, c.clean.F, c.clean.V, c.clean.F).msae;
  const double e_with = normal_errors(b.V, c.clean.F, c.clean.V, c.clean.F).msae;
  EXPECT_LT(e_with, e_without) << e_without << " -> " << e_with;
  EXPECT_EQ(preset_options("paper").plane_min_faces, 0);
  DenoiseOptions bad;
  bad.plane_min_faces = -1;
  EXPECT_THROW(denoise(c.noisy, c.clean.F, bad), InvalidInput);
}
