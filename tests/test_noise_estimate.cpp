// The noise estimate (noise_estimate.h) against seeded noise of known σ, and its invariance.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/noise.h"
#include "msmesh/noise_estimate.h"
#include "msmesh/shapes.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

Eigen::MatrixXd seeded(const Mesh& m, double sigma, NoiseDirection d = NoiseDirection::Normal, double impulsive = 0) {
  NoiseOptions o;
  o.sigma = sigma;
  o.direction = d;
  o.impulsive_fraction = impulsive;
  o.seed = 11;
  return add_noise(m.V, m.F, o);
}

// A sphere with fine bumps along its normals, a few edges across: shape detail that the low
// pass removes as it removes noise.
Mesh bumpy_sphere() {
  Mesh m = make_shape("sphere", 16);
  const double edge = mean_edge_length(m.V, m.F), h = 0.3 * edge, k = 2 * M_PI / (5 * edge);  // wavelength 5 edges
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    const Eigen::RowVector3d p = m.V.row(i), n = p.normalized();
    m.V.row(i) = p + h * std::sin(k * p.x()) * std::sin(k * p.y()) * std::sin(k * p.z()) * n;
  }
  return m;
}

}  // namespace

TEST(NoiseEstimate, FollowsSeededGaussianNoise) {
  const Mesh sphere = make_shape("sphere", 16);
  for (const double sigma : {0.1, 0.3, 0.6}) {
    const NoiseEstimate e = estimate_noise(seeded(sphere, sigma), sphere.F);
    EXPECT_NEAR(e.sigma, sigma, 0.25 * sigma) << sigma;
    EXPECT_NEAR(e.sigma_rms, e.sigma, 0.2 * e.sigma) << sigma;  // Gaussian: no outliers to speak of
    EXPECT_LT(e.outlier_fraction, 0.01) << sigma;
    EXPECT_NEAR(e.sigma_noise, sigma, 0.15 * sigma) << sigma;  // a sphere has no detail to take apart
    EXPECT_NEAR(e.sigma * e.sigma, e.sigma_noise * e.sigma_noise + e.detail * e.detail, 1e-12) << sigma;
  }
  // In random directions: the part along the normal, σ/√3.
  const NoiseEstimate r = estimate_noise(seeded(sphere, 0.6, NoiseDirection::Random), sphere.F);
  EXPECT_NEAR(r.sigma, 0.6 / std::sqrt(3.0), 0.25 * 0.6 / std::sqrt(3.0));
}

TEST(NoiseEstimate, CleanMeshesHaveLittleAndImpulsiveNoiseShowsInTheRms) {
  const Mesh sphere = make_shape("sphere", 16);
  EXPECT_LT(estimate_noise(sphere.V, sphere.F).sigma, 0.03);
  const Mesh plane = test::grid(20);
  EXPECT_LT(estimate_noise(plane.V, plane.F).sigma, 1e-12);
  const NoiseEstimate imp = estimate_noise(seeded(sphere, 0.5, NoiseDirection::Normal, 0.1), sphere.F);
  EXPECT_GT(imp.sigma_rms, 1.5 * imp.sigma);
  EXPECT_GT(imp.outlier_fraction, 0.02);
}

TEST(NoiseEstimate, FineDetailIsToldApartFromNoise) {
  const Mesh bumps = bumpy_sphere();
  const NoiseEstimate clean = estimate_noise(bumps.V, bumps.F);
  EXPECT_GT(clean.sigma, 0.05);                     // the bumps read as noise to the single low pass ...
  EXPECT_LT(clean.sigma_noise, 0.5 * clean.sigma);  // ... and mostly as shape to the two
  EXPECT_GT(clean.detail, 0.85 * clean.sigma);
  const NoiseEstimate low = estimate_noise(seeded(bumps, 0.1), bumps.F);
  EXPECT_LT(std::abs(low.sigma_noise - 0.1), 0.5 * std::abs(low.sigma - 0.1));
  EXPECT_NEAR(low.sigma_noise, 0.1, 0.1 * 0.1);
  const NoiseEstimate high = estimate_noise(seeded(bumps, 0.3), bumps.F);  // the bumps hardly count
  EXPECT_NEAR(high.sigma_noise, 0.3, 0.1 * 0.3);
  // Far beyond the measured range the split stays defined: all noise, no detail made up.
  const Mesh sphere = make_shape("sphere", 16);
  const NoiseEstimate huge = estimate_noise(seeded(sphere, 3.0), sphere.F);
  EXPECT_TRUE(std::isfinite(huge.sigma_noise) && std::isfinite(huge.detail));
  EXPECT_GT(huge.sigma_noise, 0.5 * huge.sigma);
}

TEST(NoiseEstimate, InvariantUnderScaleRotationAndTranslation) {
  const Mesh part = make_shape("fandisk", 8);
  const Eigen::MatrixXd V = seeded(part, 0.3);
  Eigen::Matrix3d R;
  R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  const Eigen::MatrixXd W = ((V * R.transpose()) * 13.0).rowwise() + Eigen::RowVector3d(5, -4, 2);
  const NoiseEstimate a = estimate_noise(V, part.F), b = estimate_noise(W, part.F);
  EXPECT_NEAR(a.sigma, b.sigma, 1e-9);
  EXPECT_NEAR(a.sigma_rms, b.sigma_rms, 1e-9);
  EXPECT_NEAR(a.sigma_noise, b.sigma_noise, 1e-9);
  EXPECT_NEAR(a.detail, b.detail, 1e-9);
  EXPECT_EQ(a.outlier_fraction, b.outlier_fraction);
  EXPECT_NE(a.summary().find("noise sigma"), std::string::npos);
}

TEST(NoiseEstimate, BadMeshesAreRefused) {
  Mesh m = test::grid(4);
  m.V(0, 0) = std::nan("");
  EXPECT_THROW(estimate_noise(m.V, m.F), InvalidInput);
}

TEST(NoiseEstimate, TellsNoiseAcrossTheNormalsFromNoiseAlongThem) {
  // Heavy noise on a part: in random directions the residuals go across the normals about
  // √2 times as far as along them (two directions across for one along); along the normals
  // mostly along them. The figure is a ratio: invariant under scale, turn and translation.
  for (const char* name : {"fandisk", "cube"}) {
    const Mesh m = make_shape(name, 24);
    for (const double sigma : {0.5, 0.7}) {
      const NoiseEstimate random = estimate_noise(seeded(m, sigma, NoiseDirection::Random), m.F);
      const NoiseEstimate along = estimate_noise(seeded(m, sigma), m.F);
      EXPECT_GT(random.across_ratio, 1.25) << name << " " << sigma;
      EXPECT_LT(random.across_ratio, 2.0) << name << " " << sigma;
      EXPECT_LT(along.across_ratio, 1.0) << name << " " << sigma;
    }
  }
  const Mesh m = make_shape("fandisk", 24);
  const Eigen::MatrixXd noisy = seeded(m, 0.7, NoiseDirection::Random);
  Eigen::Matrix3d R;
  R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized());
  const Eigen::MatrixXd moved = ((noisy * R.transpose()) * 40.0).rowwise() + Eigen::RowVector3d(5, -2, 9);
  EXPECT_NEAR(estimate_noise(moved, m.F).across_ratio, estimate_noise(noisy, m.F).across_ratio, 1e-9);
}
