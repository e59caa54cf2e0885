// Internal: planar regions of the filtered normals, snapped to their fitted planes (denoise.cpp).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "msmesh/prepared_mesh.h"

namespace msmesh::detail {

/// Neighbours across an interior edge whose normals differ by less than this join a region.
constexpr double kPlaneNeighbourDeg = 1.0;
/// A region is planar when every normal in it is within this of the region's mean normal.
constexpr double kPlaneSpreadDeg = 4.0;

/// What snap_planar_regions did.
struct PlanarRegions {
  Eigen::Index regions = 0;   ///< regions snapped
  Eigen::Index faces = 0;     ///< faces in them
  std::vector<bool> snapped;  ///< #F: whether the face is in one of them (empty when min_faces <= 0)
};

/// Finds the connected regions of faces (across interior edges) whose normals N agree: each
/// joined to a neighbour within kPlaneNeighbourDeg, all within kPlaneSpreadDeg of the region's
/// area-weighted mean; every such region of at least `min_faces` faces gets the normal of the
/// least-squares plane through its vertices (mesh.positions(): the input, which the noise
/// averages out of over the whole region), oriented like its mean. N: #F by 3 unit normals in
/// the face order of mesh, changed in place. min_faces <= 0: nothing. Deterministic; invariant
/// to the mesh's scale, position and (equivariant) rotation.
PlanarRegions snap_planar_regions(const PreparedMesh& mesh, Eigen::MatrixXd& N, int min_faces);

}  // namespace msmesh::detail
