// Internal: Taubin smoothing with the mesh's neighbour lists built once, for callers that
// smooth the same mesh more than once (the noise estimate's light and full low passes).
#pragma once
#include <Eigen/Core>

#include "msmesh/taubin.h"
#include "vertex_neighbours.h"

namespace msmesh::detail {

class TaubinSmoother {
 public:
  /// The row-normalised vertex adjacency of F (#V = num_vertices), each vertex's distinct
  /// neighbours sorted. F must be valid (validate_mesh).
  TaubinSmoother(const Eigen::MatrixXi& F, Eigen::Index num_vertices);

  /// options.iterations λ|μ pairs on X (#V by 3), exactly as taubin_smooth.
  Eigen::MatrixXd apply(const Eigen::MatrixXd& X, const TaubinOptions& options) const;

 private:
  VertexNeighbours neighbours_;
};

}  // namespace msmesh::detail
