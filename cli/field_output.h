// Writing the edge discontinuity field v: a text file (one edge per line: "i j v") or a PLY
// with the mesh's vertices and one coloured edge element per edge (features dark).
#pragma once
#include <Eigen/Core>
#include <string>

#include "msmesh/topology.h"

namespace msmesh::cli {

void write_edge_field(const std::string& path, const Eigen::MatrixXd& V, const Topology& topo, const Eigen::VectorXd& v);

/// Colour map for a value in [0,1]: dark red (0, features) through yellow to light grey (1).
Eigen::Vector3d field_color(double x);

}  // namespace msmesh::cli
