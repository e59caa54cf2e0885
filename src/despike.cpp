#include "msmesh/despike.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "low_pass_residuals.h"
#include "msmesh/errors.h"
#include "msmesh/mesh.h"

namespace msmesh {

DespikeResult despike(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double threshold) {
  if (!(threshold > 0) || !std::isfinite(threshold))
    throw InvalidInput("despike: threshold must be a finite number > 0");
  validate_mesh(V, F, "despike");
  if (F.rows() == 0) return DespikeResult{V, 0};
  return detail::despike_from(V, detail::low_pass_residuals(V, F), threshold);
}

DespikeResult detail::despike_from(const Eigen::MatrixXd& V, const LowPassResiduals& lp, double threshold) {
  DespikeResult r;
  r.V = V;
  std::vector<double> d;
  d.reserve(static_cast<std::size_t>(V.rows()));
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (lp.used[static_cast<std::size_t>(i)]) d.push_back(lp.residual(i));
  const detail::RobustSpread spread = detail::robust_spread(std::move(d));
  const double m = spread.median, sigma = spread.sigma;
  // A vertex is a spike when it stands out by more than threshold σ, and by more than round-off
  // (σ is 0 on an exactly smooth mesh such as a plane).
  const double limit = std::max(threshold * sigma, 1e-9 * lp.mean_edge);
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (lp.used[static_cast<std::size_t>(i)] && std::abs(lp.residual(i) - m) > limit) {
      r.V.row(i) -= lp.residual(i) * lp.normals.row(i);
      ++r.moved;
    }
  return r;
}

}  // namespace msmesh
