// Internal: the featureless test of preset auto (docs/presets.md, "Featureless smooth
// surfaces"). At sampled vertices a quadric height field is fitted by least squares to the
// vertex's 2-ring and to its 3-ring (in the frame of each neighbourhood's principal axes), and
// the residual variances are compared with their exact degrees of freedom:
//   excess = (Σ r₃² / Σ (m₃ − 6)) / (Σ r₂² / Σ (m₂ − 6)) − 1.
// White noise on a smooth surface leaves the same variance at both sizes (excess ≈ 0, whatever
// the tessellation and σ); detail or creases that a quadric does not follow over three rings
// make it positive (0.05–3 on the organic and CAD meshes of ../shared at σ 0.05–0.7).
#pragma once
#include <Eigen/Core>

namespace msmesh::detail {

struct QuadricRingExcess {
  double excess = 0;          ///< the ratio above minus 1 (0 when nothing was measured)
  double sigma_two_ring = 0;  ///< √(Σ r₂² / Σ (m₂ − 6)), in the mesh's units
  Eigen::Index samples = 0;   ///< vertices whose two fits were counted (0 also when no 2-ring left a residual)
};

/// Samples every ⌊#V / max_samples⌋-th vertex (so between max_samples and twice as many, or every
/// vertex; vertices with fewer than kMinRingVertices in their 2-ring are skipped). Deterministic.
QuadricRingExcess quadric_ring_excess(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                      Eigen::Index max_samples = 2000);

constexpr int kMinRingVertices = 12;

}  // namespace msmesh::detail
