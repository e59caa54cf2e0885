#include "msmesh/taubin.h"

#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/mesh.h"

namespace msmesh {

void TaubinOptions::validate() const {
  if (iterations < 0) throw InvalidInput("taubin: iterations must be >= 0, got " + std::to_string(iterations));
  if (!(lambda > 0 && lambda <= 1))
    throw InvalidInput("taubin: lambda must be in (0, 1], got " + std::to_string(lambda));
  if (!(mu >= -1 && mu < 0 && -mu > lambda))
    throw InvalidInput("taubin: mu must be in [-1, 0) with |mu| > lambda, got " + std::to_string(mu));
}

Eigen::MatrixXd taubin_smooth(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const TaubinOptions& o) {
  o.validate();
  validate_mesh(V, F, "taubin smoothing");
  // W: the row-normalised vertex adjacency (each edge once per direction).
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(F.rows()) * 6);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      t.emplace_back(F(f, k), F(f, (k + 1) % 3), 1.0);
      t.emplace_back(F(f, (k + 1) % 3), F(f, k), 1.0);
    }
  Eigen::SparseMatrix<double, Eigen::RowMajor> W(V.rows(), V.rows());
  W.setFromTriplets(t.begin(), t.end(), [](double, double) { return 1.0; });  // an edge counts once
  for (Eigen::Index i = 0; i < W.outerSize(); ++i) {
    const double n = static_cast<double>(W.outerIndexPtr()[i + 1] - W.outerIndexPtr()[i]);
    if (n == 0) continue;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(W, i); it; ++it) it.valueRef() = 1.0 / n;
  }
  // Rows without neighbours (unreferenced vertices): W V = 0 would pull them to the origin.
  std::vector<bool> isolated(static_cast<std::size_t>(V.rows()));
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    isolated[static_cast<std::size_t>(i)] = W.outerIndexPtr()[i + 1] == W.outerIndexPtr()[i];
  Eigen::MatrixXd X = V, L;
  for (int it = 0; it < o.iterations; ++it)
    for (const double step : {o.lambda, o.mu}) {
      L = W * X - X;
      for (Eigen::Index i = 0; i < X.rows(); ++i)
        if (isolated[static_cast<std::size_t>(i)]) L.row(i).setZero();
      X += step * L;
    }
  return X;
}

}  // namespace msmesh
