#include "msmesh/operators.h"

#include <vector>

#include "msmesh/geometry.h"

namespace msmesh {

using Triplet = Eigen::Triplet<double>;

SparseMatrix build_face_gradient(const Topology& topo) {
  // eq. 6: (∇_M u)_e = Σ_τ sgn(e,τ) u_τ over the two faces of an interior edge. Boundary and
  // non-manifold (or inconsistently oriented) edges get an empty row: no jump is defined there.
  std::vector<Triplet> t;
  t.reserve(static_cast<size_t>(2 * topo.num_edges()));
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    if (!topo.edge_is_interior[e]) continue;
    t.emplace_back(e, topo.edge_faces(e, 0), 1.0);   // walks e forwards
    t.emplace_back(e, topo.edge_faces(e, 1), -1.0);  // walks e backwards
  }
  SparseMatrix G(topo.num_edges(), topo.num_faces());
  G.setFromTriplets(t.begin(), t.end());
  return G;
}

SparseMatrix build_edge_gradient(const Topology& topo) {
  // eq. 9–10: the corner line l = 3f+k of face f at corner k; the edge entering corner k
  // counter-clockwise runs F(f,k−1)→F(f,k), i.e. is opposite corner k+1; the edge leaving it
  // runs F(f,k)→F(f,k+1), opposite corner k+2.
  const Eigen::Index nf = topo.num_faces();
  std::vector<Triplet> t;
  t.reserve(static_cast<size_t>(6 * nf));
  for (Eigen::Index f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index l = 3 * f + k;
      t.emplace_back(l, topo.face_edges(f, (k + 1) % 3), 1.0);
      t.emplace_back(l, topo.face_edges(f, (k + 2) % 3), -1.0);
    }
  }
  SparseMatrix D(3 * nf, topo.num_edges());
  D.setFromTriplets(t.begin(), t.end());
  return D;
}

Operators build_operators(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Topology& topo) {
  Operators ops;
  ops.G = build_face_gradient(topo);
  ops.D = build_edge_gradient(topo);
  ops.face_areas = face_areas(V, F);
  ops.edge_lengths = edge_lengths(V, topo);
  const Eigen::MatrixXd lines = corner_line_lengths(V, F);
  ops.line_lengths.resize(3 * F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) ops.line_lengths(3 * f + k) = lines(f, k);
  return ops;
}

namespace {
Eigen::VectorXd safe_inverse(const Eigen::VectorXd& w) {
  return w.unaryExpr([](double x) { return x > 0 ? 1.0 / x : 0.0; });
}
}  // namespace

Eigen::MatrixXd divergence_faces(const Operators& ops, const Eigen::MatrixXd& p) {
  return -(safe_inverse(ops.face_areas).asDiagonal() *
           (ops.G.transpose() * (ops.edge_lengths.asDiagonal() * p)));
}

Eigen::MatrixXd laplacian_faces(const Operators& ops, const Eigen::MatrixXd& u) {
  return divergence_faces(ops, ops.G * u);
}

Eigen::MatrixXd divergence_edges(const Operators& ops, const Eigen::MatrixXd& q) {
  return -(safe_inverse(ops.edge_lengths).asDiagonal() *
           (ops.D.transpose() * (ops.line_lengths.asDiagonal() * q)));
}

Eigen::MatrixXd laplacian_edges(const Operators& ops, const Eigen::MatrixXd& v) {
  return divergence_edges(ops, ops.D * v);
}

double inner_product(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::VectorXd& w) {
  return (a.cwiseProduct(b).rowwise().sum().array() * w.array()).sum();
}

}  // namespace msmesh
