// Internal: Algorithm 2 run again with new targets on the system it already built (denoise.cpp's
// jet-fitted and dropped targets; docs/presets.md, "Jet-fitted targets", "Unreachable targets").
#pragma once
#include <Eigen/Core>
#include <functional>

#include "msmesh/vertex_update.h"

namespace msmesh::detail {

/// Given the positions an update converged to (#V by 3, normalised units of the prepared mesh,
/// in its vertex numbering), replaces targets N (#F by 3) in place; returns whether it did.
using Retarget = std::function<bool(const Eigen::MatrixXd& positions, Eigen::MatrixXd& N)>;

/// update_vertices (Algorithm 2); then, when `retarget` is set and changes the targets, the
/// alternation again from the positions it reached, with the new targets and the V-step system
/// the first run assembled and factored (assembled again only where the fairness acts along the
/// normals, τ < 1, which reads the targets). The same as a second update_vertices started from
/// the first one's result, without building its system twice. The report counts both runs.
VertexUpdateResult update_vertices_retargeted(const PreparedMesh& mesh, const Eigen::MatrixXd& N,
                                              const Eigen::VectorXd& v, const VertexUpdateOptions& options,
                                              const VertexUpdateWeights& weights, const ProgressCallback& progress,
                                              const Retarget& retarget);

}  // namespace msmesh::detail
