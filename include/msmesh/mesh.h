// The mesh type: plain Eigen data, as in libigl.
#pragma once
#include <Eigen/Core>
#include <string>

namespace msmesh {

/// A triangle mesh.
///  - V: #V by 3 vertex positions.
///  - F: #F by 3 vertex indices, counter-clockwise seen from outside.
///  - vertex_colors: empty or #V by 3, RGB in [0,1]; carried through processing untouched.
///  - uv: empty or #V by 2 per-vertex texture coordinates; carried through untouched.
///  - vertex_normals: empty or #V by 3; filled when the file has normals. Commands that move
///    vertices recompute them (geometry.h vertex_normals) so that they match the result.
struct Mesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  Eigen::MatrixXd vertex_colors;
  Eigen::MatrixXd uv;
  Eigen::MatrixXd vertex_normals;

  Eigen::Index num_vertices() const { return V.rows(); }
  Eigen::Index num_faces() const { return F.rows(); }
};

/// Throws InvalidInput (message prefixed by `what`, e.g. a file name) unless V is #V by 3
/// with finite values, F is #F by 3 with indices in [0, #V), and no face repeats a vertex.
/// Zero-area faces and non-manifold configurations are accepted (the operators handle them).
void validate_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what = "mesh");

}  // namespace msmesh
