#include "msmesh/noise_estimate.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "low_pass_residuals.h"
#include "masked_measures.h"
#include "msmesh/mesh.h"

namespace msmesh {

namespace {

// The MAD of the residuals to Taubin x10 is this fraction of the seeded σ (Gaussian noise along
// the normals, σ 0.1 to 0.7, the public clean meshes: 0.83 to 0.92; docs/presets.md).
constexpr double kCalibration = 0.87;
constexpr double kOutlierSigmas = 4.0;

}  // namespace

std::string NoiseEstimate::summary() const {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(3);
  os << "noise sigma " << sigma << " (rms " << sigma_rms << ", outliers ";
  os.precision(1);
  os << 100 * outlier_fraction << " %)";
  return os.str();
}

NoiseEstimate estimate_noise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "noise estimate");
  return detail::estimate_noise_masked(V, F, nullptr);
}

NoiseEstimate detail::estimate_noise_masked(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                            const std::vector<char>* measured) {
  if (F.rows() == 0) return NoiseEstimate{};
  return estimate_noise_from(detail::low_pass_residuals(V, F), measured);
}

NoiseEstimate detail::estimate_noise_from(const LowPassResiduals& lp, const std::vector<char>* measured) {
  NoiseEstimate e;
  const double scale = lp.mean_edge;
  if (!(scale > 0)) return e;
  std::vector<double> d;
  d.reserve(lp.used.size());
  for (Eigen::Index i = 0; i < lp.residual.size(); ++i)
    if (lp.used[static_cast<std::size_t>(i)] && (!measured || (*measured)[static_cast<std::size_t>(i)]))
      d.push_back(lp.residual(i) / scale);
  if (d.empty()) return e;
  const double m = detail::median_of(d);
  std::vector<double> a(d.size());
  double sum2 = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    a[i] = std::abs(d[i] - m);
    sum2 += a[i] * a[i];
  }
  const double mad = detail::kMadToSigma * detail::median_of(a);
  e.sigma = mad / kCalibration;
  e.sigma_rms = std::sqrt(sum2 / static_cast<double>(d.size())) / kCalibration;
  std::size_t outliers = 0;
  for (const double x : a) outliers += x > kOutlierSigmas * mad;
  e.outlier_fraction = static_cast<double>(outliers) / static_cast<double>(d.size());
  return e;
}

}  // namespace msmesh
