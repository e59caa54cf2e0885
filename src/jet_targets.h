// Internal: second-order targets on the curved parts of a surface (denoise.cpp; docs/presets.md,
// "Jet-fitted targets").
#pragma once
#include <Eigen/Core>
#include <vector>

#include "msmesh/prepared_mesh.h"

namespace msmesh::detail {

/// Faces whose targets differ by more than this lie on two sides of a crease: a neighbourhood
/// does not grow across their edge.
constexpr double kJetCreaseDeg = 10.0;
/// A face whose neighbourhood's targets all lie within this of its own sits inside a plateau of
/// a flat part, whose normal averages the noise over more faces than a local fit would: kept.
constexpr double kJetFlatDeg = 3.0;
/// A fit whose RMS height residual exceeds this (mean edge lengths) meets detail that a quadric
/// cannot follow: the target is kept.
constexpr double kJetMaxResidual = 0.03;
/// Fewest vertices a fit takes (a quadric height field has six coefficients).
constexpr int kJetMinVertices = 10;

/// What fit_jet_targets did.
struct JetTargets {
  Eigen::Index faces = 0;  ///< faces whose target was replaced
};

/// Algorithm 1's normals are piecewise constant: on a curved part (a cylinder, a blend, a
/// sphere) they leave plateaus that the vertex update turns into facets. For every face, this
/// grows a neighbourhood of `rings` rings of faces across interior edges whose targets N differ
/// by less than kJetCreaseDeg, fits a quadric height field z(x, y) = ax² + bxy + cy² + dx + ey +
/// g by least squares through the neighbourhood's vertices X (#V by 3, normalised units: the
/// positions after a first vertex update, in which the noise is gone but the facets are not),
/// in the frame of the face's target centred at its centroid, and replaces the target by the
/// quadric's normal there, (−d, −e, 1). Faces are kept when their neighbourhood is flat
/// (kJetFlatDeg), the fit leaves too large a residual (kJetMaxResidual) or holds fewer than
/// kJetMinVertices vertices, and when `fixed` (#F, or empty) marks them (planar regions already
/// snapped). N: #F by 3 unit normals in the face order of mesh; every fit reads the targets as
/// they came in, and all are replaced at the end. Deterministic and independent of the thread
/// count; invariant to scale and position, equivariant under rotation.
JetTargets fit_jet_targets(const PreparedMesh& mesh, const Eigen::MatrixXd& X, Eigen::MatrixXd& N, int rings,
                           const std::vector<bool>& fixed);

}  // namespace msmesh::detail
