#include "msmesh/taubin.h"

#include <algorithm>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/mesh.h"
#include "parallel.h"
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
detail::TaubinSmoother::TaubinSmoother(const Eigen::MatrixXi& F, Eigen::Index nv)
    : start_(static_cast<std::size_t>(nv) + 1, 0), count_(static_cast<std::size_t>(nv)) {
  for (Eigen::Index i = 0; i < F.size(); ++i) start_[static_cast<std::size_t>(F.data()[i]) + 1] += 2;
  for (std::size_t i = 0; i + 1 < start_.size(); ++i) start_[i + 1] += start_[i];
  nbr_.resize(static_cast<std::size_t>(start_.back()));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      nbr_[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
      nbr_[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
    }
  detail::parallel_for(
      nv,
      [&](Eigen::Index i) {
        int* first = nbr_.data() + start_[static_cast<std::size_t>(i)];
        int* last = nbr_.data() + start_[static_cast<std::size_t>(i) + 1];
        std::sort(first, last);
        count_[static_cast<std::size_t>(i)] =
            static_cast<int>(std::unique(first, last) - first);  // an edge counts once
      },
      4);
}

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
        const int n = count_[static_cast<std::size_t>(i)];
        const int* nb = nbr_.data() + start_[static_cast<std::size_t>(i)];
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
