// Spike removal (despike.h): impulsive outliers are moved back, Gaussian noise and clean
// meshes are left (nearly) alone.
#include <gtest/gtest.h>

#include "msmesh/despike.h"
#include "msmesh/errors.h"
#include "msmesh/noise.h"
#include "msmesh/shapes.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

Eigen::MatrixXd seeded(const Mesh& m, double sigma, double impulsive) {
  NoiseOptions o;
  o.sigma = sigma;
  o.direction = NoiseDirection::Normal;
  o.impulsive_fraction = impulsive;
  o.seed = 5;
  return add_noise(m.V, m.F, o);
}

double rms_distance(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  return std::sqrt((A - B).rowwise().squaredNorm().mean());
}

}  // namespace

TEST(Despike, MovesImpulsiveOutliersBackTowardsTheSurface) {
  const Mesh sphere = make_shape("sphere", 16);
  const Eigen::MatrixXd noisy = seeded(sphere, 0.5, 0.2);
  const DespikeResult d = despike(noisy, sphere.F, 3.0);
  // About a fifth of the vertices were displaced; most of those are found, few others.
  const double moved = static_cast<double>(d.moved) / static_cast<double>(noisy.rows());
  EXPECT_GT(moved, 0.05);
  EXPECT_LT(moved, 0.25);
  EXPECT_LT(rms_distance(d.V, sphere.V), 0.6 * rms_distance(noisy, sphere.V));
  // Only the moved vertices changed.
  Eigen::Index changed = 0;
  for (Eigen::Index i = 0; i < noisy.rows(); ++i) changed += (d.V.row(i) != noisy.row(i));
  EXPECT_EQ(changed, d.moved);
}

TEST(Despike, LeavesCleanAndGaussianNoisyMeshesAlmostAlone) {
  const Mesh plane = test::grid(20);
  EXPECT_EQ(despike(plane.V, plane.F, 3.0).moved, 0);
  const Mesh sphere = make_shape("sphere", 16);
  const DespikeResult g = despike(seeded(sphere, 0.2, 0.0), sphere.F, 3.0);
  EXPECT_LT(static_cast<double>(g.moved) / static_cast<double>(sphere.V.rows()), 0.02);
}

TEST(Despike, RejectsABadThreshold) {
  const Mesh plane = test::grid(4);
  EXPECT_THROW(despike(plane.V, plane.F, 0.0), InvalidInput);
  EXPECT_THROW(despike(plane.V, plane.F, -1.0), InvalidInput);
  EXPECT_THROW(despike(plane.V, plane.F, std::nan("")), InvalidInput);
}
