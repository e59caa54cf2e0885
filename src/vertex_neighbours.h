// Internal: each vertex's distinct neighbours along the edges of a triangle mesh, sorted, as
// compressed rows (the Taubin smoother's adjacency, taubin_smoother.h, and the rings of the
// featureless test, featureless.h).
#pragma once
#include <Eigen/Core>
#include <vector>

namespace msmesh::detail {

struct VertexNeighbours {
  /// F must be valid (validate_mesh); #V = num_vertices.
  VertexNeighbours(const Eigen::MatrixXi& F, Eigen::Index num_vertices);

  /// The neighbours of vertex i: nbr[start[i] .. start[i] + count[i]), ascending (an edge once).
  std::vector<int> start, nbr, count;
  const int* begin(Eigen::Index i) const { return nbr.data() + start[static_cast<std::size_t>(i)]; }
  const int* end(Eigen::Index i) const { return begin(i) + count[static_cast<std::size_t>(i)]; }
};

}  // namespace msmesh::detail
