// Internal: the vertex-connected components of a mesh's faces, and the split into the
// components large enough to denoise and the small ones kept as they are
// (DenoiseOptions::min_component_faces).
#pragma once
#include <Eigen/Core>
#include <vector>

namespace msmesh::detail {

/// The vertex-connected component of each face (numbered in order of first face), and their
/// number in `count`.
std::vector<int> face_component_labels(const Eigen::MatrixXi& F, Eigen::Index num_vertices, int& count);

/// The faces of the components of at least `min_faces` faces, in order, and what is left out.
struct ComponentSplit {
  std::vector<Eigen::Index> large_faces;
  Eigen::Index small_components = 0;  ///< components of fewer than min_faces faces
  Eigen::Index small_faces = 0;       ///< their faces
};

/// Splits the faces by their component's size (every face is large when min_faces ≤ 1).
ComponentSplit split_small_components(const std::vector<int>& label, int count, int min_faces);

}  // namespace msmesh::detail
