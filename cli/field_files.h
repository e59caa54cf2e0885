// The edge-field and label files: the edge discontinuity field v written as text (one edge a
// line, "i j v") or as a PLY with coloured edges (`msmesh denoise --save-field`), read back
// (`msmesh render --field`), and one segment label per face (`msmesh segment --labels`).
#pragma once
#include <Eigen/Core>
#include <string>

#include "msmesh/topology.h"

namespace msmesh::cli {

/// v[e] belongs to edges.row(e) (#E by 2 vertex indices into V, #V by 3).
void write_edge_field(const std::string& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& edges,
                      const Eigen::VectorXd& v);

/// Reads an edge field written by `msmesh denoise --save-field`: the text format (one edge a
/// line, "i j v"; '#' starts a comment) or the ascii PLY (vertices, then "i j v r g b" edges).
/// Returns #E values in the edge order of `topo`; every edge of `topo` must be listed.
/// Throws IoError naming the file and line, or InvalidInput for a pair that is not an edge.
Eigen::VectorXd read_edge_field(const std::string& path, const Topology& topo);

/// Reads one integer label ≥ 0 per face (whitespace separated, '#' comments), exactly
/// `faces` of them. Throws IoError naming the file.
Eigen::VectorXi read_face_labels(const std::string& path, Eigen::Index faces);

}  // namespace msmesh::cli
