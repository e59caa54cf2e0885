// Taubin's λ|μ smoothing (Taubin 1995) with uniform (umbrella) weights: a low-pass filter of
// the vertex positions that does not shrink the mesh. msmesh uses it to pre-filter the first
// normals under heavy noise and to measure the noise (noise_estimate.h). Open3D's
// filter_smooth_taubin, which the benchmarks compare against, takes the same λ|μ pairs with
// inverse-distance weights 1/‖x_i − x_j‖ instead, so its results differ (docs/presets.md).
#pragma once
#include <Eigen/Core>

namespace msmesh {

/// Options of taubin_smooth. Each iteration is one λ step and one μ step.
struct TaubinOptions {
  int iterations = 10;  ///< λ|μ pairs (≥ 0)
  double lambda = 0.5;  ///< shrinking step, in (0, 1]
  double mu = -0.53;    ///< inflating step, in [-1, 0), |μ| > λ
  void validate() const;
};

/// #V by 3 smoothed positions of (V, F) (#V by 3, #F by 3). Vertices without a face stay.
/// Throws InvalidInput for a bad mesh or options.
Eigen::MatrixXd taubin_smooth(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const TaubinOptions& options = {});

}  // namespace msmesh
