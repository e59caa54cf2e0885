// Internal: the matrices of the face graph, diag(d) + Σ_e w(e) (1_i − 1_j)(1_i − 1_j)ᵀ over the
// interior edges e between faces i and j: the N-step's 2αS + r GᵀLG and the polish's I + L_w.
#pragma once
#include <Eigen/SparseCore>

#include "msmesh/topology.h"
#include "sparse_build.h"

namespace msmesh::detail {

/// Row f: d(f) plus w(e) on the diagonal for each interior edge e of f, −w(e) towards the face
/// across e (entries in the order of f's edges).
template <class Diagonal, class Weight>
Eigen::SparseMatrix<double> face_graph_matrix(const Topology& topo, Eigen::Index num_faces, Diagonal&& d, Weight&& w) {
  return symmetric_from_rows(
      num_faces, [](Eigen::Index) { return 4; },
      [&](Eigen::Index f, int* col, double* val) {
        int n = 1;
        double diag = d(f);
        for (int k = 0; k < 3; ++k) {
          const int e = topo.face_edges(f, k);
          if (!topo.edge_is_interior[e]) continue;
          const int g = topo.edge_faces(e, 0) == f ? topo.edge_faces(e, 1) : topo.edge_faces(e, 0);
          const double we = w(e);
          diag += we;
          col[n] = g;
          val[n++] = -we;
        }
        col[0] = static_cast<int>(f);
        val[0] = diag;
        return n;
      });
}

}  // namespace msmesh::detail
