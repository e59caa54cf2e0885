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
double crease_line_length(const Topology& t, const Eigen::VectorXd& len, const std::vector<char>& crease,
                          Eigen::Index num_vertices, double min_length);

}  // namespace msmesh::detail
