// Internal: scale normalisation to mean edge length 1 (DESIGN.md §"Scale").
#pragma once
#include <Eigen/Core>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"

namespace msmesh::detail {

struct Normalization {
  Eigen::RowVector3d center = Eigen::RowVector3d::Zero();
  double scale = 1.0;  ///< mean edge length of the input

  Eigen::MatrixXd apply(const Eigen::MatrixXd& V) const { return (V.rowwise() - center) / scale; }
  Eigen::MatrixXd undo(const Eigen::MatrixXd& Vn) const { return (Vn * scale).rowwise() + center; }
};

/// Centre on the vertex mean and scale so the mean edge length becomes 1.
inline Normalization normalization_for(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double mean_length = -1) {
  Normalization n;
  if (V.rows() > 0) n.center = V.colwise().mean();
  n.scale = mean_length > 0 ? mean_length : mean_edge_length(V, F);
  if (!(n.scale > 0) || !std::isfinite(n.scale))
    throw InvalidInput("mesh has no edge of positive length: cannot normalise its scale");
  return n;
}

}  // namespace msmesh::detail
