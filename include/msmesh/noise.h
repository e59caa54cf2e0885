// Seeded noise, as in the denoising literature: σ in units of the mean edge length.
#pragma once
#include <cstdint>

#include "msmesh/mesh.h"
#include "msmesh/parameters.h"

namespace msmesh {

/// Normal: displacement n·σ·g along the unit vertex normal n, g ~ N(0,1).
/// Random: displacement u·σ·g with u uniform on the unit sphere, g ~ N(0,1) (as the
/// GuidedDenoising code of Zhang et al. 2015, which generated the public benchmark meshes).
/// Both give an RMS displacement length of σ; an isotropic Gaussian vector with σ per
/// component would give σ√3.
enum class NoiseDirection { Normal, Random };

struct NoiseOptions {
  double sigma = 0.2;  ///< standard deviation, a multiple of the mean edge length (≥ 0)
  NoiseDirection direction = NoiseDirection::Normal;  ///< along vertex normals, or random directions
  /// 0: Gaussian noise on every vertex. In (0,1]: impulsive noise, round(fraction × #referenced
  /// vertices) vertices (at least one, chosen at random) displaced with standard deviation
  /// `sigma` in `direction` (the literature uses a large sigma, e.g. 0.5–1, and Random).
  double impulsive_fraction = 0.0;
  std::uint64_t seed = 0;  ///< in [0, 2^53] (a value a double holds exactly, as the CLI and Python pass it)
  /// 0: independent per vertex (white). k > 0: correlated, long-waved noise like a depth camera's:
  /// the per-vertex displacements are averaged with their neighbours' k times (each pass v ←
  /// (v + Σ neighbours) / (1 + degree)), then scaled back to the RMS length σ. Gaussian only (not
  /// with impulsive noise). In [0, 1000].
  int correlation = 0;
  void validate() const;  ///< throws InvalidInput naming the parameter and its valid range (noise_parameters())
};

/// sigma (in [0, 1e6]), impulsive (the fraction, in [0, 1]), seed and correlation: names, ranges and help,
/// shared by validate(), `msmesh noise` and Python (parameters.h).
const ParameterTable<NoiseOptions>& noise_parameters();

/// Returns noisy vertex positions (#V by 3); F is unchanged. Reproducible for a seed on any
/// machine (own generator and Box–Muller, no std:: distribution). σ is scaled by the mean
/// edge length of (V, F), so the result is scale invariant. Vertices no face refers to are
/// returned unchanged. Throws InvalidInput for invalid options or mesh.
Eigen::MatrixXd add_noise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const NoiseOptions& options);

}  // namespace msmesh
