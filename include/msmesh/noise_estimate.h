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
  /// `sigma` split into noise and shape (sigma² = sigma_noise² + detail²): the shape's fine
  /// detail and creases, which the low pass also removes, grow with the low pass's strength and
  /// white noise's residual does not, so the residuals after 3 and after 10 iterations tell them
  /// apart (docs/presets.md, "Noise and detail"). On a clean detailed mesh sigma reads 0.03–0.1;
  /// sigma_noise reads 0–0.05.
  double sigma_noise = 0;
  double detail = 0;
  /// RMS of the residuals' part across the normals (V − S less its part along them) over their
  /// RMS along them: which way the noise goes, once it is well above the triangulation's own
  /// irregularity (σ_rms ≳ 0.25). Noise in random directions reads 1.3–1.9 there (two directions
  /// across for one along), noise along the normals 0.1–1.0 (1.17 on an irregular Kinect scan)
  /// (docs/presets.md, "Heavy noise in random directions on CAD parts").
  double across_ratio = 0;
  std::string summary()
      const;  ///< "noise sigma 0.310 (rms 0.330, outliers 0.2 %; shape detail 0.050, noise alone 0.306)"
};

/// Estimates the noise of (V, F) (#V by 3, #F by 3). Throws InvalidInput for a bad mesh.
NoiseEstimate estimate_noise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace msmesh
