// Seeded noise (msmesh/noise.h): reproducibility, the σ scale, impulsive fraction, correlation, options.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/noise.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

/// Number of rows of A that differ from B.
Eigen::Index moved_rows(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  Eigen::Index n = 0;
  for (Eigen::Index i = 0; i < A.rows(); ++i) n += (A.row(i) != B.row(i)) ? 1 : 0;
  return n;
}

NoiseOptions options(double sigma, NoiseDirection dir = NoiseDirection::Normal, double impulsive = 0,
                     std::uint64_t seed = 7) {
  NoiseOptions o;
  o.sigma = sigma;
  o.direction = dir;
  o.impulsive_fraction = impulsive;
  o.seed = seed;
  return o;
}

}  // namespace

TEST(Noise, ReproducibleForASeed) {
  const Mesh m = test::grid(20, 0.3);
  for (auto dir : {NoiseDirection::Normal, NoiseDirection::Random})
    for (double imp : {0.0, 0.2}) {
      const Eigen::MatrixXd a = add_noise(m.V, m.F, options(0.3, dir, imp, 42));
      const Eigen::MatrixXd b = add_noise(m.V, m.F, options(0.3, dir, imp, 42));
      EXPECT_TRUE(a == b);  // bit for bit
    }
}

TEST(Noise, DiffersBetweenSeeds) {
  const Mesh m = test::grid(20, 0.3);
  for (auto dir : {NoiseDirection::Normal, NoiseDirection::Random}) {
    const Eigen::MatrixXd a = add_noise(m.V, m.F, options(0.3, dir, 0, 1));
    const Eigen::MatrixXd b = add_noise(m.V, m.F, options(0.3, dir, 0, 2));
    EXPECT_EQ(moved_rows(a, b), m.V.rows());
  }
}

TEST(Noise, StreamIsPinned) {
  // The generator is our own (xoshiro256** + Box–Muller), so these values hold on any
  // platform up to libm's last bits; a change here breaks every seeded experiment.
  const Mesh m = test::grid(2);  // flat: vertex normals are +z
  const Eigen::MatrixXd out = add_noise(m.V, m.F, options(1.0, NoiseDirection::Normal, 0, 0));
  const double l = mean_edge_length(m.V, m.F);
  const Eigen::VectorXd g = (out - m.V).col(2) / l;
  EXPECT_TRUE(((out - m.V).leftCols(2).array() == 0).all());
  const double expected[3] = {-0.01896499060631051, -1.3559302271143727, -0.40372109705088766};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(g(i), expected[i], 1e-12) << i;
}

TEST(Noise, ZeroSigmaLeavesVerticesUnchanged) {
  const Mesh m = test::grid(10, 0.3);
  for (auto dir : {NoiseDirection::Normal, NoiseDirection::Random})
    for (double imp : {0.0, 0.5}) EXPECT_TRUE(add_noise(m.V, m.F, options(0.0, dir, imp)) == m.V);
}

TEST(Noise, NormalDisplacementHasStandardDeviationSigmaTimesMeanEdge) {
  const Mesh m = test::grid(70, 0.3);  // 5041 vertices
  const double sigma = 0.25;
  const double l = mean_edge_length(m.V, m.F);
  const Eigen::MatrixXd N = vertex_normals(m.V, m.F);
  const Eigen::MatrixXd D = add_noise(m.V, m.F, options(sigma)) - m.V;
  // Along the normal only: the tangential part vanishes.
  const Eigen::VectorXd along = (D.array() * N.array()).rowwise().sum();
  EXPECT_LT((D - along.asDiagonal() * N).cwiseAbs().maxCoeff(), 1e-12 * l);
  const double mean = along.mean();
  const double std = std::sqrt((along.array() - mean).square().sum() / double(along.size() - 1));
  EXPECT_NEAR(std, sigma * l, 0.1 * sigma * l);
  EXPECT_NEAR(mean, 0.0, 0.1 * sigma * l);
}

TEST(Noise, RandomDirectionHasRmsLengthSigmaTimesMeanEdge) {
  const Mesh m = test::grid(70, 0.3);
  const double sigma = 0.25;
  const double l = mean_edge_length(m.V, m.F);
  const Eigen::MatrixXd D = add_noise(m.V, m.F, options(sigma, NoiseDirection::Random)) - m.V;
  const double rms = std::sqrt(D.rowwise().squaredNorm().mean());
  EXPECT_NEAR(rms, sigma * l, 0.1 * sigma * l);
  // Isotropic: each component carries about a third of the energy.
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(D.col(c).squaredNorm() / D.squaredNorm(), 1.0 / 3.0, 0.05) << c;
}

TEST(Noise, ImpulsiveMovesThatFractionOfVertices) {
  const Mesh m = test::grid(40, 0.3);  // 1681 vertices
  for (double frac : {0.05, 0.3, 1.0})
    for (auto dir : {NoiseDirection::Normal, NoiseDirection::Random}) {
      const Eigen::MatrixXd out = add_noise(m.V, m.F, options(0.8, dir, frac));
      EXPECT_EQ(moved_rows(out, m.V), std::llround(frac * double(m.V.rows()))) << frac;
    }
  // A tiny positive fraction still moves one vertex.
  EXPECT_EQ(moved_rows(add_noise(m.V, m.F, options(0.8, NoiseDirection::Normal, 1e-9)), m.V), 1);
}

TEST(Noise, IsolatedVerticesUntouched) {
  Mesh m = test::grid(6, 0.3);
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) << 5, 5, 5;
  for (auto dir : {NoiseDirection::Normal, NoiseDirection::Random})
    for (double imp : {0.0, 1.0}) {
      const Eigen::MatrixXd out = add_noise(m.V, m.F, options(0.5, dir, imp));
      EXPECT_TRUE(out.row(m.V.rows() - 1) == m.V.row(m.V.rows() - 1));
      EXPECT_EQ(moved_rows(out, m.V), m.V.rows() - 1);
    }
}

TEST(Noise, ScaleInvariant) {
  const Mesh m = test::grid(10, 0.3);
  const Eigen::MatrixXd a = add_noise(m.V, m.F, options(0.3));
  const Eigen::MatrixXd b = add_noise(1000.0 * m.V, m.F, options(0.3));
  EXPECT_LT((1000.0 * a - b).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Noise, InvalidOptionsThrow) {
  const Mesh m = test::tetrahedron();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double s : {-0.1, nan, inf}) {
    EXPECT_THROW(options(s).validate(), InvalidInput) << s;
    EXPECT_THROW(add_noise(m.V, m.F, options(s)), InvalidInput) << s;
  }
  for (double f : {-0.1, 1.5, nan})
    EXPECT_THROW(add_noise(m.V, m.F, options(0.2, NoiseDirection::Normal, f)), InvalidInput);
  try {
    options(-2).validate();
    FAIL();
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("sigma"), std::string::npos) << msg;
    EXPECT_NE(msg.find("-2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("[0, 1000000]"), std::string::npos) << msg;
  }
  try {
    options(0.2, NoiseDirection::Normal, 3).validate();
    FAIL();
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("impulsive"), std::string::npos) << msg;  // named as in the CLI and Python
    EXPECT_NE(msg.find("[0, 1]"), std::string::npos) << msg;
  }
  EXPECT_NO_THROW(NoiseOptions{}.validate());
  // An invalid mesh is refused too.
  Eigen::MatrixXi bad = m.F;
  bad(0, 0) = 9;
  EXPECT_THROW(add_noise(m.V, bad, options(0.2)), InvalidInput);
}

TEST(Noise, CorrelatedKeepsTheRmsLengthAndIsLongWaved) {
  // Averaging over neighbours k times, then scaling back: the RMS displacement stays that of the
  // white draw (σ × mean edge, to sampling), while neighbouring vertices move alike - the
  // difference across an edge shrinks as k grows (white noise: √2 × the RMS).
  const Mesh m = test::grid(70, 0.3);
  const double l = mean_edge_length(m.V, m.F);
  const Topology topo = build_topology(m.F, m.V.rows());
  auto across_edges = [&](const Eigen::MatrixXd& D) {
    double s = 0;
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
      s += (D.row(topo.edges(e, 0)) - D.row(topo.edges(e, 1))).squaredNorm();
    return std::sqrt(s / double(topo.num_edges()));
  };
  for (auto dir : {NoiseDirection::Normal, NoiseDirection::Random}) {
    NoiseOptions o = options(0.25, dir);
    const Eigen::MatrixXd white = add_noise(m.V, m.F, o) - m.V;
    double previous = across_edges(white);
    for (int k : {1, 4, 16}) {
      o.correlation = k;
      const Eigen::MatrixXd D = add_noise(m.V, m.F, o) - m.V;
      EXPECT_NEAR(D.norm(), white.norm(), 1e-9 * white.norm()) << k;
      EXPECT_NEAR(std::sqrt(D.rowwise().squaredNorm().mean()), 0.25 * l, 0.1 * 0.25 * l) << k;
      const double a = across_edges(D);
      EXPECT_LT(a, 0.7 * previous) << k;
      previous = a;
      EXPECT_TRUE(D == add_noise(m.V, m.F, o) - m.V) << k;  // reproducible, bit for bit
    }
    EXPECT_LT(previous, 0.2 * across_edges(white));
  }
  // Normal noise on a flat grid stays along the normal (+z), whatever the correlation.
  const Mesh flat = test::grid(30);
  NoiseOptions o = options(0.25);
  o.correlation = 3;
  EXPECT_TRUE(((add_noise(flat.V, flat.F, o) - flat.V).leftCols(2).array() == 0).all());
}

TEST(Noise, CorrelationLeavesIsolatedVerticesAndRefusesImpulsive) {
  Mesh m = test::grid(6, 0.3);
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) << 5, 5, 5;
  NoiseOptions o = options(0.5);
  o.correlation = 2;
  const Eigen::MatrixXd out = add_noise(m.V, m.F, o);
  EXPECT_TRUE(out.row(m.V.rows() - 1) == m.V.row(m.V.rows() - 1));
  EXPECT_EQ(moved_rows(out, m.V), m.V.rows() - 1);
  // Scale invariant like the white noise.
  const Eigen::MatrixXd b = add_noise(1000.0 * m.V, m.F, o);
  EXPECT_LT((1000.0 * out - b).cwiseAbs().maxCoeff(), 1e-9);
  o.impulsive_fraction = 0.1;
  try {
    o.validate();
    FAIL();
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("correlation"), std::string::npos) << msg;
    EXPECT_NE(msg.find("impulsive"), std::string::npos) << msg;
  }
  o.impulsive_fraction = 0;
  for (int k : {-1, 1001}) {
    o.correlation = k;
    EXPECT_THROW(add_noise(m.V, m.F, o), InvalidInput) << k;
  }
}
