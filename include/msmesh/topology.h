// Connectivity of a triangle mesh: unique undirected edges with a fixed orientation,
// the faces on each side, and the sign sgn(e, τ) of DESIGN.md §"Spaces and operators".
#pragma once
#include <Eigen/Core>
#include <vector>

namespace msmesh {

/// Connectivity only; no positions.
struct Topology {
  /// #E by 2: edge e goes from edges(e,0) to edges(e,1), with edges(e,0) < edges(e,1).
  Eigen::MatrixXi edges;
  /// #F by 3: face_edges(f,k) is the edge opposite corner k, i.e. from F(f,k+1) to F(f,k+2).
  Eigen::MatrixXi face_edges;
  /// #F by 3: +1 when face f walks face_edges(f,k) in the edge's direction, else -1.
  Eigen::MatrixXi face_edge_signs;
  /// #E by 2: the faces incident to e; for an interior manifold edge the first walks e
  /// forwards (sgn +1) where orientation is consistent. -1 where absent (boundary edge).
  /// For a non-manifold edge (3 or more faces) both entries are the first two faces seen.
  Eigen::MatrixXi edge_faces;
  /// #E: number of faces incident to e (1 boundary, 2 interior, >2 non-manifold).
  Eigen::VectorXi edge_face_count;
  /// #E: true for an interior manifold edge: two faces walking it in opposite directions.
  /// Only these edges carry a gradient (the others get an empty row of G, eq. 6).
  std::vector<bool> edge_is_interior;
  /// Number of vertices the face indices refer to (may exceed the referenced count).
  Eigen::Index num_vertices = 0;

  Eigen::Index num_edges() const { return edges.rows(); }
  Eigen::Index num_faces() const { return face_edges.rows(); }
};

/// Builds the connectivity of F (#F by 3 indices into num_vertices vertices).
Topology build_topology(const Eigen::MatrixXi& F, Eigen::Index num_vertices);

/// Counts and loops describing the mesh's structure, for `msmesh info` and hole finding.
struct TopologySummary {
  Eigen::Index boundary_edges = 0;
  Eigen::Index non_manifold_edges = 0;
  Eigen::Index non_manifold_vertices = 0;  ///< vertices whose face fan is not one disk/half-disk
  Eigen::Index unreferenced_vertices = 0;
  Eigen::Index inconsistently_oriented_edges = 0;  ///< two faces walking an edge the same way
  Eigen::Index components = 0;                     ///< connected components of faces
  /// Boundary loops as ordered vertex cycles (only through manifold boundary vertices).
  std::vector<std::vector<int>> boundary_loops;
};

/// Computes the summary for F and its topology.
TopologySummary summarize_topology(const Eigen::MatrixXi& F, const Topology& topo);

/// Connected components of the faces (sharing an edge). Returns #F labels in [0, count).
Eigen::VectorXi face_components(const Topology& topo, int* count = nullptr);

}  // namespace msmesh
