#include "msmesh/prepared_mesh.h"

#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "normalize.h"

namespace msmesh {

PreparedMesh::PreparedMesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what) : faces_(F) {
  validate_mesh(V, F, what);
  topology_ = build_topology(F, V.rows());
  if (F.rows() == 0) {
    positions_ = V;  // nothing to normalise against; the solvers return such meshes unchanged
    return;
  }
  const detail::Normalization norm = detail::normalization_for(V, F, edge_lengths(V, topology_).mean());
  center_ = norm.center;
  scale_ = norm.scale;
  positions_ = norm.apply(V);
}

Eigen::MatrixXd PreparedMesh::to_input_units(const Eigen::MatrixXd& positions) const {
  detail::Normalization norm;
  norm.center = center_;
  norm.scale = scale_;
  return norm.undo(positions);
}

}  // namespace msmesh
