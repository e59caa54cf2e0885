// The noise estimate (noise_estimate.h) against seeded noise of known σ, and its invariance.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "msmesh/errors.h"
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

}  // namespace

TEST(NoiseEstimate, FollowsSeededGaussianNoise) {
  const Mesh sphere = make_shape("sphere", 16);
  for (const double sigma : {0.1, 0.3, 0.6}) {
    const NoiseEstimate e = estimate_noise(seeded(sphere, sigma), sphere.F);
    EXPECT_NEAR(e.sigma, sigma, 0.25 * sigma) << sigma;
    EXPECT_NEAR(e.sigma_rms, e.sigma, 0.2 * e.sigma) << sigma;  // Gaussian: no outliers to speak of
    EXPECT_LT(e.outlier_fraction, 0.01) << sigma;
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

TEST(NoiseEstimate, InvariantUnderScaleRotationAndTranslation) {
  const Mesh part = make_shape("fandisk", 8);
  const Eigen::MatrixXd V = seeded(part, 0.3);
  Eigen::Matrix3d R;
  R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  const Eigen::MatrixXd W = ((V * R.transpose()) * 13.0).rowwise() + Eigen::RowVector3d(5, -4, 2);
  const NoiseEstimate a = estimate_noise(V, part.F), b = estimate_noise(W, part.F);
  EXPECT_NEAR(a.sigma, b.sigma, 1e-9);
  EXPECT_NEAR(a.sigma_rms, b.sigma_rms, 1e-9);
  EXPECT_EQ(a.outlier_fraction, b.outlier_fraction);
  EXPECT_NE(a.summary().find("noise sigma"), std::string::npos);
}

TEST(NoiseEstimate, BadMeshesAreRefused) {
  Mesh m = test::grid(4);
  m.V(0, 0) = std::nan("");
  EXPECT_THROW(estimate_noise(m.V, m.F), InvalidInput);
}
