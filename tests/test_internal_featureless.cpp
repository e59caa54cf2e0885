// The featureless test of preset auto (src/featureless.h): white noise on a smooth surface
// leaves the same quadric residual at two and three rings, detail and creases do not; the
// figure does not depend on the mesh's position, turn or scale; a noisy torus is denoised as
// class cad with the strong polish, and better than by the class smooth.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "featureless.h"
#include "msmesh/denoise.h"
#include "msmesh/geometry.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"

using namespace msmesh;

namespace {

Eigen::MatrixXd noisy(const Mesh& m, double sigma, unsigned seed) {
  NoiseOptions no;
  no.sigma = sigma;
  no.seed = seed;
  return add_noise(m.V, m.F, no);
}

// The torus with bumps eight edges wide (`amplitude_edges` high) along its vertex normals: detail, as on a statue.
Mesh bumpy(const Mesh& m, double amplitude_edges) {
  Mesh b = m;
  const Eigen::MatrixXd N = vertex_normals(m.V, m.F);
  const double h = mean_edge_length(m.V, m.F), k = 2 * M_PI / (8 * h);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    const Eigen::RowVector3d p = m.V.row(i);
    b.V.row(i) += amplitude_edges * h * std::sin(k * p.x()) * std::sin(k * p.y()) * std::sin(k * p.z()) * N.row(i);
  }
  return b;
}

}  // namespace

TEST(InternalFeatureless, WhiteNoiseOnASmoothSurfaceHasNoExcess) {
  // Near 0 (this torus, 7.5° between neighbours around its tube, reads 0.04–0.06: the quadric's
  // own error over three rings; at σ 0.05 0.13, where the limit is 0.3), against 0.3 for bumps
  // and 0.8 for creases below.
  for (const Mesh& m : {make_torus(96, 48), make_sphere(4)}) {
    for (double sigma : {0.1, 0.2, 0.4}) {
      const Eigen::MatrixXd V = noisy(m, sigma, 3);
      const detail::QuadricRingExcess q = detail::quadric_ring_excess(V, m.F);
      EXPECT_GT(q.samples, 1000);
      EXPECT_LT(std::abs(q.excess), 0.08) << "sigma " << sigma;
      // The two-ring residual is the noise along the normals (σ in mean edge lengths).
      EXPECT_NEAR(q.sigma_two_ring / mean_edge_length(m.V, m.F), sigma, 0.1 * sigma + 0.005) << "sigma " << sigma;
    }
  }
}

TEST(InternalFeatureless, DetailAndCreasesHaveAnExcess) {
  const Mesh torus = make_torus(96, 48);
  const detail::QuadricRingExcess bumps = detail::quadric_ring_excess(noisy(bumpy(torus, 0.3), 0.1, 3), torus.F);
  EXPECT_GT(bumps.excess, 0.2);  // the limit at σ 0.1: 0.16
  const Mesh cube = make_cube(24);
  const detail::QuadricRingExcess creases = detail::quadric_ring_excess(noisy(cube, 0.1, 3), cube.F);
  EXPECT_GT(creases.excess, 0.5);
}

TEST(InternalFeatureless, TheExcessTurnsWithTheMeshAndIgnoresScaleAndPosition) {
  const Mesh m = make_torus(64, 32);
  const Eigen::MatrixXd V = noisy(m, 0.2, 5);
  const detail::QuadricRingExcess a = detail::quadric_ring_excess(V, m.F);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::MatrixXd W = ((V * R.transpose()) * 37.5).rowwise() + Eigen::RowVector3d(5, -3, 11);
  const detail::QuadricRingExcess b = detail::quadric_ring_excess(W, m.F);
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_NEAR(a.excess, b.excess, 1e-9);
  EXPECT_NEAR(b.sigma_two_ring, 37.5 * a.sigma_two_ring, 1e-9 * b.sigma_two_ring);
}

TEST(InternalFeatureless, NothingToMeasure) {
  const detail::QuadricRingExcess q = detail::quadric_ring_excess(Eigen::MatrixXd(0, 3), Eigen::MatrixXi(0, 3));
  EXPECT_EQ(q.samples, 0);
  EXPECT_EQ(q.excess, 0);
  // A cube pressed flat (every vertex in the plane z = 0), without noise: every fit is exact, so
  // there is nothing to compare (and auto does not call it featureless on that ground).
  Mesh plane = make_cube(8);
  plane.V.col(2).setZero();
  const detail::QuadricRingExcess flat = detail::quadric_ring_excess(plane.V, plane.F);
  EXPECT_EQ(flat.samples, 0);
  // Too few neighbours anywhere (a single triangle): nothing measured either.
  const Eigen::MatrixXd T = (Eigen::MatrixXd(3, 3) << 0, 0, 0, 1, 0, 0, 0, 1, 0).finished();
  const Eigen::MatrixXi G = (Eigen::MatrixXi(1, 3) << 0, 1, 2).finished();
  EXPECT_EQ(detail::quadric_ring_excess(T, G).samples, 0);
}

TEST(InternalFeatureless, AutoDenoisesANoisyTorusAsFeatureless) {
  const Mesh torus = make_torus(96, 48);
  const Eigen::MatrixXd V = noisy(torus, 0.1, 7);
  const ResolvedPreset r = resolve_preset("auto", V, torus.F);
  ASSERT_TRUE(r.featureless) << r.reason();
  EXPECT_EQ(r.preset, "cad");
  EXPECT_EQ(r.options.normals.polish, 100.0);
  EXPECT_EQ(r.options.vertices.omega2, 3.0);
  EXPECT_EQ(r.options.vertices.omega3, preset_options("cad").vertices.omega3);
  EXPECT_NE(r.reason().find("featureless"), std::string::npos) << r.reason();
  // The class smooth for the same noise, as before the test: far more error left.
  const DenoiseResult featureless = denoise(V, torus.F, r.options);
  const DenoiseResult smooth = denoise(V, torus.F, adaptive_options("smooth", r.sigma, 0.0));
  const double a = evaluate(featureless.V, torus.F, torus.V, torus.F).normals.msae;
  const double b = evaluate(smooth.V, torus.F, torus.V, torus.F).normals.msae;
  EXPECT_LT(a, 0.5 * b) << a << " against " << b;
  // With bumps the same noise is not featureless.
  const ResolvedPreset w = resolve_preset("auto", noisy(bumpy(torus, 0.3), 0.1, 7), torus.F);
  EXPECT_FALSE(w.featureless) << w.reason();
  EXPECT_GT(w.quadric_excess, w.featureless_limit) << w.reason();
}
