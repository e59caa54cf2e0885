// Whole-mesh figures for `msmesh info` and msmesh.info(): surface area, enclosed volume,
// watertightness, Euler characteristic, boundary loops and genus, per connected component and
// for the whole mesh.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace msmesh {

/// One connected component of faces (faces sharing an edge; face_components() of topology.h).
struct ComponentStatistics {
  Eigen::Index faces = 0;
  Eigen::Index vertices = 0;  ///< vertices its faces use
  Eigen::Index edges = 0;     ///< edges of its faces
  double area = 0;
  /// Every edge of the component has exactly two faces (no boundary, no non-manifold edge).
  bool closed = false;
  /// Its faces can be oriented consistently (false for a Moebius strip or a Klein bottle, and
  /// for components with non-manifold edges, which have no orientation).
  bool orientable = false;
  /// Adjacent faces walk each shared edge in opposite directions, as the file lists them.
  bool consistently_oriented = false;
  /// Manifold: no non-manifold edge and no non-manifold vertex.
  bool manifold = false;
  /// Closed components only: the enclosed volume (divergence theorem, sum of p0·(p1×p2)/6).
  /// Signed when consistently oriented (negative: the faces point inwards); for a closed
  /// orientable component listed with mixed orientations, the volume of the consistently
  /// re-oriented surface, made positive. 0 for open or non-orientable components.
  double volume = 0;
  /// V − E + F of the component.
  Eigen::Index euler_characteristic = 0;
  /// Boundary loops (holes and outer boundaries) of the component.
  Eigen::Index boundary_loops = 0;
  /// For a manifold orientable component: (2 − χ − b) / 2, the number of handles (torus 1,
  /// sphere and disk 0); -1 when it is not defined (non-manifold or non-orientable).
  Eigen::Index genus = -1;
};

/// The figures of a whole mesh.
struct MeshStatistics {
  double area = 0;  ///< total surface area (zero-area faces add nothing)
  /// Sum of the volumes of the closed components (ComponentStatistics::volume); 0 when none is
  /// closed (closed_components tells the two cases apart).
  double volume = 0;
  Eigen::Index components = 0;
  Eigen::Index closed_components = 0;
  /// Every edge has exactly two faces, walked in opposite directions (consistently oriented),
  /// and there is at least one face.
  bool watertight = false;
  Eigen::Index euler_characteristic = 0;  ///< V − E + F over the vertices the faces use
  Eigen::Index boundary_loops = 0;
  /// Sum of the components' genus; -1 when some component has no genus.
  Eigen::Index genus = -1;
  std::vector<ComponentStatistics> per_component;  ///< in the order of face_components()
};

/// Computes the statistics of (V, F). Throws InvalidInput for an invalid mesh (validate_mesh).
MeshStatistics mesh_statistics(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace msmesh
