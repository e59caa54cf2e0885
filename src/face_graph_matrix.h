// Internal: the matrices of the face graph, diag(d) + Σ_e w(e) (1_i − 1_j)(1_i − 1_j)ᵀ over the
// interior edges e between faces i and j: the N-step's 2αS + r GᵀLG and the polish's I + L_w.
#pragma once
#include <Eigen/SparseCore>

#include "msmesh/topology.h"
#include "pcg.h"
#include "sparse_build.h"

namespace msmesh::detail {

/// Row f: its diagonal entry d(f) plus w(e) for each interior edge e of f into *diag, and
/// −w(e) towards the face across e into cols and vals (in the order of f's edges); returns
/// their number.
template <class Diagonal, class Weight>
int face_graph_row(const Topology& topo, Eigen::Index f, const Diagonal& d, const Weight& w, double* diag, int* cols,
                   double* vals) {
  int n = 0;
  *diag = d(f);
  for (int k = 0; k < 3; ++k) {
    const int e = topo.face_edges(f, k);
    if (!topo.edge_is_interior[e]) continue;
    const int g = topo.edge_faces(e, 0) == f ? topo.edge_faces(e, 1) : topo.edge_faces(e, 0);
    const double we = w(e);
    *diag += we;
    cols[n] = g;
    vals[n++] = -we;
  }
  return n;
}

/// The matrix assembled (for the factorisation).
template <class Diagonal, class Weight>
Eigen::SparseMatrix<double> face_graph_matrix(const Topology& topo, Eigen::Index num_faces, Diagonal&& d, Weight&& w) {
  return symmetric_from_rows(
      num_faces, [](Eigen::Index) { return 4; },
      [&](Eigen::Index f, int* col, double* val) {
        col[0] = static_cast<int>(f);
        return 1 + face_graph_row(topo, f, d, w, val, col + 1, val + 1);
      });
}

/// The matrix as rows for the conjugate gradients' fixed-width layout (pcg.h: no assembled
/// matrix). Keeps references to topo, d and w.
template <class Diagonal, class Weight>
FixedWidthRows face_graph_rows(const Topology& topo, const Diagonal& d, const Weight& w) {
  return [&topo, &d, &w](Eigen::Index f, double* diag, int* cols, double* vals) {
    return face_graph_row(topo, f, d, w, diag, cols, vals);
  };
}

}  // namespace msmesh::detail
