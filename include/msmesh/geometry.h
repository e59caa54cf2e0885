// Per-element geometric quantities. Lengths and areas are in the mesh's own units.
#pragma once
#include <Eigen/Core>

#include "msmesh/topology.h"

namespace msmesh {

/// #F face areas s_τ (space U weights).
Eigen::VectorXd face_areas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// #F by 3 unit face normals (eq. 14); zero rows for degenerate faces.
Eigen::MatrixXd face_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// #F by 3 face barycentres.
Eigen::MatrixXd face_barycenters(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// #E edge lengths len(e) (space V weights).
Eigen::VectorXd edge_lengths(const Eigen::MatrixXd& V, const Topology& topo);

/// #F by 3: length of the line from the barycentre of face f to its corner k (space W
/// weights; line index l = 3 f + k).
Eigen::MatrixXd corner_line_lengths(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// Mean length of the unique edges of F (0 for a mesh without faces).
double mean_edge_length(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// #V by 3 unit vertex normals, area-weighted average of incident face normals
/// (zero rows for isolated vertices).
Eigen::MatrixXd vertex_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// Length of the diagonal of the axis-aligned bounding box of all rows of V.
double bounding_box_diagonal(const Eigen::MatrixXd& V);

/// #E dihedral angle in radians between the normals of the two faces of each interior
/// edge (0 = flat); 0 for boundary and non-manifold edges.
Eigen::VectorXd dihedral_angles(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Topology& topo);

}  // namespace msmesh
