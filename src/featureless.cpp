#include "featureless.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "msmesh/geometry.h"
#include "vertex_neighbours.h"

namespace msmesh::detail {

namespace {

constexpr int kQuadricTerms = 6;  // 1, u, v, u², uv, v²

// The sum of squared residuals of the least-squares quadric height field through the points P
// (rows), in the frame of their principal axes (height along the least one); false when the
// points do not determine the six coefficients.
bool quadric_residual(const Eigen::MatrixXd& P, double& sum_squares) {
  const Eigen::RowVector3d c = P.colwise().mean();
  const Eigen::MatrixXd Q = P.rowwise() - c;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(Q.transpose() * Q);
  const Eigen::MatrixXd L = Q * eig.eigenvectors();  // columns: least to largest spread
  const Eigen::Index m = P.rows();
  Eigen::MatrixXd X(m, kQuadricTerms);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double u = L(i, 2), v = L(i, 1);
    X.row(i) << 1.0, u, v, u * u, u * v, v * v;
  }
  const Eigen::VectorXd w = L.col(0);
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(X.transpose() * X);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return false;
  const Eigen::VectorXd coef = ldlt.solve(X.transpose() * w);
  sum_squares = (w - X * coef).squaredNorm();
  return true;
}

}  // namespace

QuadricRingExcess quadric_ring_excess(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index max_samples) {
  QuadricRingExcess out;
  const Eigen::Index nv = V.rows();
  if (nv == 0 || F.rows() == 0 || max_samples <= 0) return out;
  const VertexNeighbours neighbours(F, nv);
  // Distances are measured in the mean edge length, so the fits are well scaled at any size.
  const double h = mean_edge_length(V, F);
  if (!(h > 0)) return out;

  const Eigen::Index stride = std::max<Eigen::Index>(1, nv / max_samples);
  std::vector<int> mark(static_cast<size_t>(nv), -1), ring;
  double ss2 = 0, ss3 = 0, dof2 = 0, dof3 = 0;
  for (Eigen::Index s = 0; s < nv; s += stride) {
    const int seed = static_cast<int>(s);
    if (neighbours.count[static_cast<size_t>(seed)] == 0) continue;  // unreferenced
    // Breadth-first rings 1, 2, 3 around the seed; `mark` holds the seed for those reached.
    ring.assign(1, seed);
    mark[seed] = seed;
    size_t two_ring = 0;
    size_t from = 0;
    for (int depth = 1; depth <= 3; ++depth) {
      const size_t to = ring.size();
      for (size_t q = from; q < to; ++q)
        for (const int* n = neighbours.begin(ring[q]); n != neighbours.end(ring[q]); ++n) {
          const int j = *n;
          if (mark[j] != seed) {
            mark[j] = seed;
            ring.push_back(j);
          }
        }
      from = to;
      if (depth == 2) two_ring = ring.size();
    }
    if (two_ring < static_cast<size_t>(kMinRingVertices)) continue;
    Eigen::MatrixXd P(static_cast<Eigen::Index>(ring.size()), 3);
    for (size_t q = 0; q < ring.size(); ++q) P.row(static_cast<Eigen::Index>(q)) = V.row(ring[q]) / h;
    double r2 = 0, r3 = 0;
    if (!quadric_residual(P.topRows(static_cast<Eigen::Index>(two_ring)), r2) || !quadric_residual(P, r3)) continue;
    ss2 += r2;
    ss3 += r3;
    dof2 += static_cast<double>(two_ring) - kQuadricTerms;
    dof3 += static_cast<double>(ring.size()) - kQuadricTerms;
    ++out.samples;
  }
  if (!(ss2 > 0)) {  // every 2-ring exactly a quadric (no noise at all): nothing to compare
    out.samples = 0;
    return out;
  }
  out.excess = (ss3 / dof3) / (ss2 / dof2) - 1.0;
  out.sigma_two_ring = std::sqrt(ss2 / dof2) * h;
  return out;
}

}  // namespace msmesh::detail
