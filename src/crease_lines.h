// Internal: how much of a mesh's crease length lies on long lines, for the shape rule
// (presets.cpp, docs/presets.md "Crease lines").
#pragma once
#include <Eigen/Core>
#include <vector>

#include "msmesh/topology.h"

namespace msmesh::detail {

/// The total length of the crease edges (`crease[e]` true) that lie on a line of creases at
/// least `min_length` long: crease edges meeting at a vertex form one line, and a line counts
/// whole or not at all. `len` holds the edge lengths of `t`, `num_vertices` the mesh's #V.
/// `open` (optional, #V) marks the vertices where the measured part of a mesh ends (a patch
/// sample's cut): a line that reaches one may go on beyond, and counts whatever its length.
double crease_line_length(const Topology& t, const Eigen::VectorXd& len, const std::vector<char>& crease,
                          Eigen::Index num_vertices, double min_length, const std::vector<char>* open = nullptr);

}  // namespace msmesh::detail
