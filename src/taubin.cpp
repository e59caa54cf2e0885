#include "msmesh/taubin.h"

#include <string>

#include "msmesh/errors.h"
#include "msmesh/mesh.h"
#include "taubin_smoother.h"

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
  return detail::TaubinSmoother(F, V.rows()).apply(V, o);
}

// W: the row-normalised vertex adjacency (each edge once per direction), as the sorted
// neighbours of each vertex (CSR); W X is summed in that order.
detail::TaubinSmoother::TaubinSmoother(const Eigen::MatrixXi& F, Eigen::Index nv) : neighbours_(F, nv) {}

Eigen::MatrixXd detail::TaubinSmoother::apply(const Eigen::MatrixXd& V, const TaubinOptions& o) const {
  // Rows without neighbours (unreferenced vertices) do not move: W V = 0 would pull them to the
  // origin. Each step is X ← X + step (W X − X), coordinate by coordinate, in rows.
  const Eigen::Index nv = V.rows();
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  Rows X = V, Xn(nv, 3);
  for (int it = 0; it < o.iterations; ++it)
    for (const double step : {o.lambda, o.mu}) {
#pragma omp parallel for schedule(static) if (nv >= 8192)
      for (Eigen::Index i = 0; i < nv; ++i) {
        const int n = neighbours_.count[static_cast<std::size_t>(i)];
        const int* nb = neighbours_.begin(i);
        const double w = n > 0 ? 1.0 / n : 0.0;
        for (int c = 0; c < 3; ++c) {
          double sum = 0;
          for (int j = 0; j < n; ++j) sum += w * X(nb[j], c);
          const double l = n > 0 ? sum - X(i, c) : 0.0;
          Xn(i, c) = X(i, c) + step * l;
        }
      }
      X.swap(Xn);
    }
  return Eigen::MatrixXd(X);
}

}  // namespace msmesh
