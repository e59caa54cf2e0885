#include "msmesh/operators.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "msmesh/geometry.h"

namespace msmesh {

using Triplet = Eigen::Triplet<double>;

namespace {

// Builds a matrix whose rows have at most two entries straight in compressed row-major form
// (entries[r] = {col_a, val_a, col_b, val_b}, col −1 for none) and converts it to Eigen's
// column-major storage: linear time, much faster than setFromTriplets at a million faces.
template <class RowFn>
SparseMatrix two_per_row(Eigen::Index rows, Eigen::Index cols, RowFn&& row) {
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> R(rows, cols);
  std::vector<int> outer(static_cast<size_t>(rows) + 1, 0), inner;
  std::vector<double> val;
  inner.reserve(static_cast<size_t>(2 * rows));
  val.reserve(static_cast<size_t>(2 * rows));
  for (Eigen::Index r = 0; r < rows; ++r) {
    int c0, c1;
    double v0, v1;
    row(r, c0, v0, c1, v1);
    if (c0 >= 0 && c1 >= 0 && c0 == c1) {
      v0 += v1;
      c1 = -1;
    }
    if (c0 >= 0 && c1 >= 0 && c1 < c0) {
      std::swap(c0, c1);
      std::swap(v0, v1);
    }
    for (auto [c, v] : {std::pair<int, double>{c0, v0}, std::pair<int, double>{c1, v1}})
      if (c >= 0) {
        inner.push_back(c);
        val.push_back(v);
      }
    outer[static_cast<size_t>(r) + 1] = static_cast<int>(inner.size());
  }
  R.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), R.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), R.innerIndexPtr());
  std::copy(val.begin(), val.end(), R.valuePtr());
  return SparseMatrix(R);
}

}  // namespace

SparseMatrix build_face_gradient(const Topology& topo) {
  // eq. 6: (∇_M u)_e = Σ_τ sgn(e,τ) u_τ over the two faces of an interior edge. Boundary and
  // non-manifold (or inconsistently oriented) edges get an empty row: no jump is defined there.
  return two_per_row(topo.num_edges(), topo.num_faces(), [&](Eigen::Index e, int& c0, double& v0, int& c1, double& v1) {
    c0 = c1 = -1;
    v0 = v1 = 0;
    if (!topo.edge_is_interior[e]) return;
    c0 = topo.edge_faces(e, 0);  // walks e forwards
    v0 = 1.0;
    c1 = topo.edge_faces(e, 1);  // walks e backwards
    v1 = -1.0;
  });
}

SparseMatrix build_edge_gradient(const Topology& topo) {
  // eq. 9–10: the corner line l = 3f+k of face f at corner k; the edge entering corner k
  // counter-clockwise runs F(f,k−1)→F(f,k), i.e. is opposite corner k+1; the edge leaving it
  // runs F(f,k)→F(f,k+1), opposite corner k+2.
  return two_per_row(3 * topo.num_faces(), topo.num_edges(),
                     [&](Eigen::Index l, int& c0, double& v0, int& c1, double& v1) {
                       const Eigen::Index f = l / 3;
                       const int k = static_cast<int>(l % 3);
                       c0 = topo.face_edges(f, (k + 1) % 3);
                       v0 = 1.0;
                       c1 = topo.face_edges(f, (k + 2) % 3);
                       v1 = -1.0;
                     });
}

Operators build_operators(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Topology& topo, bool matrices) {
  Operators ops;
  if (matrices) {
    ops.G = build_face_gradient(topo);
    ops.D = build_edge_gradient(topo);
  }
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
  return -(safe_inverse(ops.face_areas).asDiagonal() * (ops.G.transpose() * (ops.edge_lengths.asDiagonal() * p)));
}

Eigen::MatrixXd laplacian_faces(const Operators& ops, const Eigen::MatrixXd& u) {
  return divergence_faces(ops, ops.G * u);
}

Eigen::MatrixXd divergence_edges(const Operators& ops, const Eigen::MatrixXd& q) {
  return -(safe_inverse(ops.edge_lengths).asDiagonal() * (ops.D.transpose() * (ops.line_lengths.asDiagonal() * q)));
}

Eigen::MatrixXd laplacian_edges(const Operators& ops, const Eigen::MatrixXd& v) {
  return divergence_edges(ops, ops.D * v);
}

double inner_product(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::VectorXd& w) {
  return (a.cwiseProduct(b).rowwise().sum().array() * w.array()).sum();
}

}  // namespace msmesh
