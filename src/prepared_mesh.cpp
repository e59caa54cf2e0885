#include "msmesh/prepared_mesh.h"

#include <algorithm>
#include <mutex>

#include "cuthill_mckee.h"
#include "face_graph_matrix.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "normalize.h"
#include "parallel.h"

namespace msmesh {

struct PreparedMesh::Orders {
  std::once_flag once;
  std::vector<int> faces;
};

PreparedMesh::PreparedMesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what)
    : faces_(F), orders_(std::make_shared<Orders>()) {
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

const std::vector<int>& PreparedMesh::face_order() const {
  std::call_once(orders_->once, [&] {
    // The graph of the face-graph matrices (face_graph_matrix.h): each face's distinct
    // neighbours across its interior edges, so the order is the one their solvers would find.
    const Eigen::Index nf = num_faces();
    std::vector<int> nbr(static_cast<size_t>(3 * nf)), degree(static_cast<size_t>(nf));
    const auto none = [](Eigen::Index) { return 0.0; };
    detail::parallel_for(nf, [&](Eigen::Index f) {
      int* c = nbr.data() + 3 * f;
      double diag = 0, vals[3];
      const int m = detail::face_graph_row(topology_, f, none, none, &diag, c, vals);
      int u = 0;
      for (int a = 0; a < m; ++a)
        if (std::find(c, c + u, c[a]) == c + u) c[u++] = c[a];
      degree[static_cast<size_t>(f)] = 1 + u;
    });
    orders_->faces = detail::reverse_cuthill_mckee(degree, [&](int f, auto&& visit) {
      for (int k = 0; k + 1 < degree[static_cast<size_t>(f)]; ++k) visit(nbr[static_cast<size_t>(3 * f + k)]);
    });
  });
  return orders_->faces;
}

Eigen::MatrixXd PreparedMesh::to_input_units(const Eigen::MatrixXd& positions) const {
  detail::Normalization norm;
  norm.center = center_;
  norm.scale = scale_;
  return norm.undo(positions);
}

}  // namespace msmesh
