// Taubin λ|μ smoothing (taubin.h): identities first (a plane stays a plane, zero iterations and
// isolated vertices change nothing, translation and scale commute), then that it removes noise
// without shrinking.
#include <gtest/gtest.h>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/noise.h"
#include "msmesh/shapes.h"
#include "msmesh/taubin.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Taubin, ZeroIterationsAndIsolatedVerticesChangeNothing) {
  Mesh m = test::grid(6);
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) << 5, 6, 7;  // no face refers to it
  TaubinOptions o;
  o.iterations = 0;
  EXPECT_EQ(taubin_smooth(m.V, m.F, o), m.V);
  o.iterations = 5;
  const Eigen::MatrixXd S = taubin_smooth(m.V, m.F, o);
  EXPECT_EQ(S.row(S.rows() - 1), m.V.row(m.V.rows() - 1));
}

TEST(Taubin, APlaneStaysInItsPlane) {
  const Mesh m = test::grid(8);
  const Eigen::MatrixXd S = taubin_smooth(m.V, m.F);
  EXPECT_LT(S.col(2).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(Taubin, CommutesWithTranslationAndScale) {
  const Mesh m = test::noisy(make_shape("sphere", 6), 0.3);
  const Eigen::RowVector3d t(3, -2, 10);
  const Eigen::MatrixXd a = taubin_smooth(m.V, m.F);
  const Eigen::MatrixXd b = taubin_smooth((m.V * 7.0).rowwise() + t, m.F);
  EXPECT_LT((((b.rowwise() - t) / 7.0) - a).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Taubin, RemovesNoiseWithoutShrinking) {
  const Mesh sphere = make_shape("sphere", 12);
  NoiseOptions no;
  no.sigma = 0.3;
  no.seed = 4;
  const Eigen::MatrixXd noisy = add_noise(sphere.V, sphere.F, no);
  const Eigen::MatrixXd S = taubin_smooth(noisy, sphere.F);
  const double r = sphere.V.rowwise().norm().mean();
  auto radial_rms = [&](const Eigen::MatrixXd& X) {
    return std::sqrt((X.rowwise().norm().array() - r).square().mean());
  };
  EXPECT_LT(radial_rms(S), 0.5 * radial_rms(noisy));
  EXPECT_NEAR(S.rowwise().norm().mean(), r, 0.01 * r);  // λ|μ: no shrinkage to speak of
}

TEST(Taubin, BadOptionsAreRefused) {
  const Mesh m = test::grid(4);
  for (const auto& [it, lambda, mu] :
       {std::tuple{-1, 0.5, -0.53}, std::tuple{1, 0.0, -0.53}, std::tuple{1, 0.5, 0.1}, std::tuple{1, 0.5, -0.4}}) {
    TaubinOptions o;
    o.iterations = it;
    o.lambda = lambda;
    o.mu = mu;
    EXPECT_THROW(taubin_smooth(m.V, m.F, o), InvalidInput) << it << " " << lambda << " " << mu;
  }
}
