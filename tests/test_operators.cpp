// operators.h: identities of the paper's operators (DESIGN.md §"Spaces and operators"): adjointness,
// ∇ of a constant is 0, Laplacians symmetric negative semidefinite in their inner products,
// on a closed mesh, an open mesh with boundary and a mesh with a non-manifold edge.
#include <gtest/gtest.h>

#include <random>

#include "msmesh/geometry.h"
#include "msmesh/operators.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

struct Case {
  std::string name;
  Mesh mesh;
};

std::vector<Case> cases() {
  return {{"tetrahedron", test::tetrahedron()}, {"grid", test::grid(6, 0.3)}, {"fin", test::fin()}};
}

Eigen::MatrixXd random_field(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index i = 0; i < m.size(); ++i) m(i) = u(gen);
  return m;
}

}  // namespace

TEST(Operators, GradientOfConstantIsZero) {
  for (const auto& c : cases()) {
    const Topology t = build_topology(c.mesh.F, c.mesh.V.rows());
    const Operators ops = build_operators(c.mesh.V, c.mesh.F, t);
    const Eigen::VectorXd u = Eigen::VectorXd::Constant(t.num_faces(), 2.5);
    EXPECT_LT((ops.G * u).norm(), 1e-14) << c.name;
    const Eigen::VectorXd v = Eigen::VectorXd::Constant(t.num_edges(), -1.5);
    EXPECT_LT((ops.D * v).norm(), 1e-14) << c.name;
  }
}

TEST(Operators, DivergenceIsMinusAdjointOfGradient) {
  unsigned seed = 1;
  for (const auto& c : cases()) {
    const Topology t = build_topology(c.mesh.F, c.mesh.V.rows());
    const Operators ops = build_operators(c.mesh.V, c.mesh.F, t);
    const Eigen::MatrixXd u = random_field(t.num_faces(), 3, seed++);
    const Eigen::MatrixXd p = random_field(t.num_edges(), 3, seed++);
    // (∇u, p)_V = −(u, div p)_U
    const double lhs = inner_product(ops.G * u, p, ops.edge_lengths);
    const double rhs = -inner_product(u, divergence_faces(ops, p), ops.face_areas);
    EXPECT_NEAR(lhs, rhs, 1e-12 * (1 + std::abs(lhs))) << c.name;
    // (∇_E v, q)_W = −(v, div_E q)_V
    const Eigen::MatrixXd v = random_field(t.num_edges(), 1, seed++);
    const Eigen::MatrixXd q = random_field(3 * t.num_faces(), 1, seed++);
    const double lhs2 = inner_product(ops.D * v, q, ops.line_lengths);
    const double rhs2 = -inner_product(v, divergence_edges(ops, q), ops.edge_lengths);
    EXPECT_NEAR(lhs2, rhs2, 1e-12 * (1 + std::abs(lhs2))) << c.name;
  }
}

TEST(Operators, LaplaciansSymmetricNegativeSemidefinite) {
  unsigned seed = 100;
  for (const auto& c : cases()) {
    const Topology t = build_topology(c.mesh.F, c.mesh.V.rows());
    const Operators ops = build_operators(c.mesh.V, c.mesh.F, t);
    for (int trial = 0; trial < 5; ++trial) {
      const Eigen::MatrixXd a = random_field(t.num_faces(), 1, seed++);
      const Eigen::MatrixXd b = random_field(t.num_faces(), 1, seed++);
      const double ab = inner_product(laplacian_faces(ops, a), b, ops.face_areas);
      const double ba = inner_product(a, laplacian_faces(ops, b), ops.face_areas);
      EXPECT_NEAR(ab, ba, 1e-12 * (1 + std::abs(ab))) << c.name;
      EXPECT_LE(inner_product(laplacian_faces(ops, a), a, ops.face_areas), 1e-14) << c.name;

      const Eigen::MatrixXd x = random_field(t.num_edges(), 1, seed++);
      const Eigen::MatrixXd y = random_field(t.num_edges(), 1, seed++);
      const double xy = inner_product(laplacian_edges(ops, x), y, ops.edge_lengths);
      const double yx = inner_product(x, laplacian_edges(ops, y), ops.edge_lengths);
      EXPECT_NEAR(xy, yx, 1e-12 * (1 + std::abs(xy))) << c.name;
      EXPECT_LE(inner_product(laplacian_edges(ops, x), x, ops.edge_lengths), 1e-14) << c.name;
    }
  }
}

TEST(Operators, BoundaryAndNonManifoldEdgesHaveEmptyGradientRows) {
  const Mesh fin = test::fin();
  const Topology t = build_topology(fin.F, fin.V.rows());
  const Operators ops = build_operators(fin.V, fin.F, t);
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    if (t.edge_is_interior[e]) continue;
    EXPECT_EQ(ops.G.row(e).norm(), 0.0);
  }
  EXPECT_EQ(ops.G.nonZeros(), 0);  // every edge of the fin is boundary or non-manifold
}

TEST(Operators, WeightsOnlyLeaveTheMatricesEmpty) {
  const Mesh m = make_cube(3);
  const Topology t = build_topology(m.F, m.V.rows());
  const Operators all = build_operators(m.V, m.F, t), weights = build_operators(m.V, m.F, t, false);
  EXPECT_EQ(weights.G.nonZeros(), 0);
  EXPECT_EQ(weights.D.nonZeros(), 0);
  EXPECT_GT(all.G.nonZeros(), 0);
  EXPECT_EQ(weights.face_areas, all.face_areas);
  EXPECT_EQ(weights.edge_lengths, all.edge_lengths);
  EXPECT_EQ(weights.line_lengths, all.line_lengths);
}
