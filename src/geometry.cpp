#include "msmesh/geometry.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "parallel.h"

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
  detail::parallel_for(F.rows(),
                       [&](Eigen::Index f) { B.row(f) = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))) / 3.0; });
  return B;
}

Eigen::VectorXd edge_lengths(const Eigen::MatrixXd& V, const Topology& topo) {
  Eigen::VectorXd l(topo.num_edges());
  detail::parallel_for(topo.num_edges(),
                       [&](Eigen::Index e) { l(e) = (V.row(topo.edges(e, 0)) - V.row(topo.edges(e, 1))).norm(); });
  return l;
}

Eigen::MatrixXd corner_line_lengths(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::MatrixXd L(F.rows(), 3);
  detail::parallel_for(F.rows(), [&](Eigen::Index f) {
    const Eigen::RowVector3d b = (V.row(F(f, 0)) + V.row(F(f, 1)) + V.row(F(f, 2))) / 3.0;
    for (int k = 0; k < 3; ++k) L(f, k) = (V.row(F(f, k)) - b).norm();
  });
  return L;
}

double mean_edge_length(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  if (F.rows() == 0) return 0.0;
  // The unique edges in build_topology's numbering (by lower, then higher vertex), without the
  // rest of the topology: the same lengths in the same order, so the same mean to the last bit,
  // at about a third of the cost (it is taken several times per denoise).
  const Eigen::Index nf = F.rows(), nv = V.rows();
  bool plain = F.cols() == 3;
  for (Eigen::Index f = 0; f < nf && plain; ++f)
    for (int k = 0; k < 3; ++k) plain = plain && F(f, k) >= 0 && F(f, k) < nv;
  if (!plain) {  // (build_topology names what is wrong)
    const Topology t = build_topology(F, V.rows());
    return edge_lengths(V, t).mean();
  }
  std::vector<int> start(static_cast<size_t>(nv) + 1, 0);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++start[static_cast<size_t>(std::min(F(f, (k + 1) % 3), F(f, (k + 2) % 3))) + 1];
  for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<int> hi(static_cast<size_t>(3 * nf));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = F(f, (k + 1) % 3), b = F(f, (k + 2) % 3);
        hi[static_cast<size_t>(fill[static_cast<size_t>(std::min(a, b))]++)] = std::max(a, b);
      }
  }
  // Each vertex's higher neighbours sorted and made unique in place (in parallel), then the
  // edges numbered by a prefix over the vertices and measured in that order.
  std::vector<int> edge_start(static_cast<size_t>(nv) + 1, 0);
  detail::parallel_for(
      nv,
      [&](Eigen::Index v) {
        const auto b = hi.begin() + start[static_cast<size_t>(v)], e = hi.begin() + start[static_cast<size_t>(v) + 1];
        std::sort(b, e);
        edge_start[static_cast<size_t>(v) + 1] = static_cast<int>(std::unique(b, e) - b);
      },
      4);
  for (Eigen::Index v = 0; v < nv; ++v) edge_start[v + 1] += edge_start[v];
  Eigen::VectorXd l(static_cast<Eigen::Index>(edge_start.back()));
  detail::parallel_for(
      nv,
      [&](Eigen::Index v) {
        const int* h = hi.data() + start[static_cast<size_t>(v)];
        for (int e = edge_start[v]; e < edge_start[v + 1]; ++e) l(e) = (V.row(v) - V.row(*h++)).norm();
      },
      4);
  return l.mean();
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
