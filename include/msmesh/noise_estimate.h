// How noisy a mesh is, from the mesh alone: the input of the noise-adaptive defaults
// (presets.h, adaptive_options). Lengths in units of the mean edge length, as every parameter.
#pragma once
#include <Eigen/Core>
#include <string>

namespace msmesh {

/// What estimate_noise measured. The residual of a vertex is its distance along the normal
/// from a low-pass copy of the mesh (taubin_smooth, 10 iterations): the noise plus the part of
/// the shape the low pass removes (creases, fine detail), which the median keeps out.
struct NoiseEstimate {
  /// Robust standard deviation of the noise along the normals (1.4826 × median absolute
  /// residual, calibrated on seeded noise: docs/presets.md, "Noise estimate"). For noise in
  /// random directions of RMS length σ this estimates σ/√3, the part that tilts the faces.
  double sigma = 0;
  double sigma_rms = 0;         ///< RMS of the same residuals (well above sigma under impulsive noise)
  double outlier_fraction = 0;  ///< fraction of vertices whose residual exceeds 4 sigma
  std::string summary() const;  ///< one line: "noise sigma 0.31 (rms 0.33, outliers 0.2 %)"
};

/// Estimates the noise of (V, F) (#V by 3, #F by 3). Throws InvalidInput for a bad mesh.
NoiseEstimate estimate_noise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace msmesh
