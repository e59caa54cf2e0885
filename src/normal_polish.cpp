#include "normal_polish.h"

#include <algorithm>
#include <cmath>

#include "face_graph_matrix.h"
#include "msmesh/topology.h"
#include "parallel.h"
#include "pcg.h"
#include "unit_rows.h"

namespace msmesh::detail {

Eigen::MatrixXd polish_normals(const PreparedMesh& mesh, const Eigen::MatrixXd& N, const Eigen::VectorXd& v,
                               double weight, double range) {
  const Topology& topo = mesh.topology();
  const Eigen::MatrixXd& P = mesh.positions();
  const Eigen::Index nf = mesh.num_faces(), ne = topo.num_edges();
  // The weight of each interior edge, from the unpolished normals.
  Eigen::VectorXd w = Eigen::VectorXd::Zero(ne);
  const double inv_two_sigma2 = 1.0 / (2 * range * range);
  parallel_for(ne, [&](Eigen::Index e) {
    if (!topo.edge_is_interior[e]) return;
    const double ve = std::clamp(v(e), 0.0, 1.0);
    const double d2 = (N.row(topo.edge_faces(e, 0)) - N.row(topo.edge_faces(e, 1))).squaredNorm();
    const double len = (P.row(topo.edges(e, 0)) - P.row(topo.edges(e, 1))).norm();
    w(e) = weight * ve * ve * std::exp(-d2 * inv_two_sigma2) * len;
  });
  // I + (the face-graph Laplacian of w): symmetric, diagonally dominant (κ ≤ 1 + 6 λ max len).
  const auto one = [](Eigen::Index) { return 1.0; };
  const auto edge_weight = [&](int e) { return w(e); };
  // Chebyshev iteration on Gershgorin's interval from N, to a tight residual (a few dozen
  // sweeps: the result is the same to round-off whatever the mesh's orientation), in the
  // faces' reverse Cuthill–McKee order (the mesh's, which the N-step's CG also works in).
  // One pass per sweep where CG made three, for a few sweeps more: the 82K sphere 42 CG sweeps
  // against 50, the 1.3M one's polish 36 % fewer CPU samples (docs/performance.md).
  BlockPcg pcg(nf, face_graph_rows(topo, one, edge_weight), mesh.face_order());
  pcg.use_chebyshev(/*gershgorin_lower=*/true);
  const RowMatrixX3 B = N;
  RowMatrixX3 X = N;
  pcg.solve(B, X, 1e-10, 10000, "normal polish");
  normalize_rows(X, B);
  return X;
}

}  // namespace msmesh::detail
