#include "msmesh/geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace msmesh {

namespace {
inline Eigen::Vector3d row3(const Eigen::MatrixXd& V, int i) { return V.row(i).transpose(); }
}  // namespace

Eigen::VectorXd face_areas(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::VectorXd a(F.rows());
#pragma omp parallel for schedule(static) if (F.rows() >= 32768)
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d p0 = row3(V, F(f, 0)), p1 = row3(V, F(f, 1)), p2 = row3(V, F(f, 2));
    a(f) = 0.5 * (p1 - p0).cross(p2 - p0).norm();
  }
  return a;
}

Eigen::MatrixXd face_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::MatrixXd N(F.rows(), 3);
#pragma omp parallel for schedule(static) if (F.rows() >= 32768)
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d p0 = row3(V, F(f, 0)), p1 = row3(V, F(f, 1)), p2 = row3(V, F(f, 2));
    // eq. 14: (v1 − v2) × (v3 − v2) with the paper's 1-based corners is (p1−p0)×(p2−p0) here
    // up to orientation; we use the counter-clockwise right-hand rule.
    Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
    const double len = n.norm();
    if (len > 0) n /= len;
    N.row(f) = n.transpose();
  }
  return N;
}

Eigen::MatrixXd face_barycenters(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::MatrixXd B(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) B.row(f) = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))) / 3.0;
  return B;
}

Eigen::VectorXd edge_lengths(const Eigen::MatrixXd& V, const Topology& topo) {
  Eigen::VectorXd l(topo.num_edges());
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) l(e) = (V.row(topo.edges(e, 0)) - V.row(topo.edges(e, 1))).norm();
  return l;
}

Eigen::MatrixXd corner_line_lengths(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::MatrixXd L(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector3d b = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))) / 3.0;
    for (int k = 0; k < 3; ++k) L(f, k) = (V.row(F(f, k)) - b).norm();
  }
  return L;
}

double mean_edge_length(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  if (F.rows() == 0) return 0.0;
  const Topology t = build_topology(F, V.rows());
  return edge_lengths(V, t).mean();
}

Eigen::MatrixXd vertex_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d p0 = row3(V, F(f, 0)), p1 = row3(V, F(f, 1)), p2 = row3(V, F(f, 2));
    const Eigen::RowVector3d n = (p1 - p0).cross(p2 - p0).transpose();  // 2 × area × unit normal
    for (int k = 0; k < 3; ++k) N.row(F(f, k)) += n;
  }
  for (Eigen::Index i = 0; i < N.rows(); ++i) {
    const double len = N.row(i).norm();
    if (len > 0) N.row(i) /= len;
  }
  return N;
}

double bounding_box_diagonal(const Eigen::MatrixXd& V) {
  if (V.rows() == 0) return 0.0;
  return (V.colwise().maxCoeff() - V.colwise().minCoeff()).norm();
}

Eigen::VectorXd dihedral_angles(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Topology& topo) {
  const Eigen::MatrixXd N = face_normals(V, F);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(topo.num_edges());
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    if (!topo.edge_is_interior[e]) continue;
    const double c = N.row(topo.edge_faces(e, 0)).dot(N.row(topo.edge_faces(e, 1)));
    a(e) = std::acos(std::clamp(c, -1.0, 1.0));
  }
  return a;
}

}  // namespace msmesh
