// Impulsive outliers ("spikes"): vertices that stand out from a low-pass copy of the mesh by
// far more than the rest. Removing them before the normals are filtered is what impulsive
// noise needs (docs/presets.md, "Impulsive noise"); preset "auto" does it when the noise
// estimate finds many outliers. Lengths are relative (robust σ of the mesh's own residuals).
#pragma once
#include <Eigen/Core>

namespace msmesh {

struct DespikeResult {
  Eigen::MatrixXd V;       ///< #V by 3 positions: the spikes moved onto the low-pass surface, the rest unchanged
  Eigen::Index moved = 0;  ///< how many vertices were moved
};

/// Each vertex's distance r along the normal from a Taubin λ|μ low pass (10 iterations, as
/// estimate_noise) is compared with the robust σ of all of them (1.4826 × the median absolute
/// deviation): a vertex with |r − median| > threshold × σ is moved by −r along the normal (onto
/// the low-pass surface). threshold > 0. Throws InvalidInput for a bad mesh or threshold.
DespikeResult despike(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double threshold);

}  // namespace msmesh
