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
// Noise and shape apart (docs/presets.md, "Noise and detail"): the robust σ of the residuals to
// the light (×3) and the full (×10) low pass, s₃ and s₁₀, are modelled as s₃² = n²/ρ² + d²,
// s₁₀² = n² + g²d², n the noise's part and d the shape's. White noise: s₁₀/s₃ = ρ, the median
// over the 48 public clean meshes with seeded noise 1.375, 1.371, 1.387, 1.411 at σ 0.2, 0.3,
// 0.5, 0.7 (1.33–1.44 between meshes): ρ = 1.372 + 0.13 max(0, s₁₀ − 0.28), held at 1.45 beyond
// the measured range (s₁₀ ≈ 0.9, σ ≈ 1; ρ must stay below g). The shape's detail
// and creases grow more, by g = s₁₀/s₃ of the clean meshes: 1.5–2.1 on the organic ones (the
// dragon 1.8), more on CAD parts, whose creases grow most. g = 2 subtracts a little less than
// the detail of the CAD parts and a little more than the smoothest statues'. The split is only
// as good as ρ: 2 % off in ρ reads as detail of 0.28 σ, so at heavy noise the detail is coarse.
constexpr double kNoiseGrowth = 1.372, kNoiseGrowthSlope = 0.13, kNoiseGrowthFrom = 0.28, kNoiseGrowthMax = 1.45;
constexpr double kDetailGrowth = 2.0;

}  // namespace

std::string NoiseEstimate::summary() const {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(3);
  os << "noise sigma " << sigma << " (rms " << sigma_rms << ", outliers ";
  os.precision(1);
  os << 100 * outlier_fraction << " %; shape detail ";
  os.precision(3);
  os << detail << ", noise alone " << sigma_noise << ")";
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
  std::vector<double> d, light;
  d.reserve(lp.used.size());
  light.reserve(lp.used.size());
  double along2 = 0, across2 = 0;
  for (Eigen::Index i = 0; i < lp.residual.size(); ++i)
    if (lp.used[static_cast<std::size_t>(i)] && (!measured || (*measured)[static_cast<std::size_t>(i)])) {
      d.push_back(lp.residual(i) / scale);
      light.push_back(lp.light_residual(i) / scale);
      along2 += lp.residual(i) * lp.residual(i);
      across2 += lp.across(i) * lp.across(i);
    }
  if (d.empty()) return e;
  e.across_ratio = along2 > 0 ? std::sqrt(across2 / along2) : 0;
  const detail::RobustSpread spread = detail::robust_spread(d);
  const double m = spread.median, mad = spread.sigma;
  std::vector<double> a(d.size());
  double sum2 = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    a[i] = std::abs(d[i] - m);
    sum2 += a[i] * a[i];
  }
  e.sigma = mad / kCalibration;
  e.sigma_rms = std::sqrt(sum2 / static_cast<double>(d.size())) / kCalibration;
  std::size_t outliers = 0;
  for (const double x : a) outliers += x > kOutlierSigmas * mad;
  e.outlier_fraction = static_cast<double>(outliers) / static_cast<double>(d.size());
  const double s3 = detail::robust_spread(std::move(light)).sigma, g2 = kDetailGrowth * kDetailGrowth;
  const double rho =
      std::min(kNoiseGrowth + kNoiseGrowthSlope * std::max(0.0, mad - kNoiseGrowthFrom), kNoiseGrowthMax);
  const double n2 = std::clamp((g2 * s3 * s3 - mad * mad) / (g2 / (rho * rho) - 1), 0.0, mad * mad);
  e.sigma_noise = std::sqrt(n2) / kCalibration;
  e.detail = std::sqrt(mad * mad - n2) / kCalibration;
  return e;
}

}  // namespace msmesh
