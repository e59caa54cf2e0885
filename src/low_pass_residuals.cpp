#include "low_pass_residuals.h"

#include <algorithm>
#include <cmath>

#include "msmesh/geometry.h"
#include "msmesh/taubin.h"
#include "taubin_smoother.h"

namespace msmesh::detail {

LowPassResiduals low_pass_residuals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  LowPassResiduals r;
  // Taubin's iterations are a fixed linear map applied in turn: the light pass followed by the
  // rest is the full low pass, bit for bit.
  const TaubinSmoother smoother(F, V.rows());
  TaubinOptions to;
  to.iterations = kLightPassIterations;
  const Eigen::MatrixXd light = smoother.apply(V, to);
  to.iterations = kLowPassIterations - kLightPassIterations;
  r.smooth = smoother.apply(light, to);
  r.normals = vertex_normals(r.smooth, F);
  r.mean_edge = mean_edge_length(r.smooth, F);
  r.used.assign(static_cast<std::size_t>(V.rows()), false);
  for (Eigen::Index i = 0; i < F.size(); ++i) r.used[static_cast<std::size_t>(F.data()[i])] = true;
  r.residual.resize(V.rows());
  r.across.resize(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const Eigen::RowVector3d d = V.row(i) - r.smooth.row(i);
    r.residual(i) = d.dot(r.normals.row(i));
    r.across(i) = (d - r.residual(i) * r.normals.row(i)).norm();
  }
  const Eigen::MatrixXd light_normals = vertex_normals(light, F);
  r.light_residual.resize(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i) r.light_residual(i) = (V.row(i) - light.row(i)).dot(light_normals.row(i));
  return r;
}

double median_of(std::vector<double> x) {
  if (x.empty()) return 0;
  const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

RobustSpread robust_spread(std::vector<double> x) {
  RobustSpread r;
  r.median = median_of(x);
  for (double& v : x) v = std::abs(v - r.median);
  r.sigma = kMadToSigma * median_of(std::move(x));
  return r;
}

}  // namespace msmesh::detail
