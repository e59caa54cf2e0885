// Seeded noise, as in the denoising literature: σ in units of the mean edge length.
#pragma once
#include <cstdint>

#include "msmesh/mesh.h"

namespace msmesh {

enum class NoiseDirection { Normal, Random };

struct NoiseOptions {
  double sigma = 0.2;  ///< standard deviation, a multiple of the mean edge length (≥ 0)
  NoiseDirection direction = NoiseDirection::Normal;  ///< along vertex normals, or random directions
  /// 0: Gaussian noise on every vertex. In (0,1]: impulsive noise, this fraction of vertices
  /// (chosen at random) displaced with standard deviation `sigma`.
  double impulsive_fraction = 0.0;
  std::uint64_t seed = 0;
  void validate() const;  ///< throws InvalidInput naming the parameter and its valid range
};

/// Returns noisy vertex positions (#V by 3); F is unchanged. Reproducible for a seed on any
/// machine (own generator and Box–Muller, no std:: distribution).
Eigen::MatrixXd add_noise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const NoiseOptions& options);

}  // namespace msmesh
