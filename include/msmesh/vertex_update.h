// Algorithm 2 of the paper: vertex updating (eq. 24–27), DESIGN.md §"Algorithm 2".
//
// Moves the vertices so that the face normals match target normals, minimising
//   ω₁ Σ_i ‖M V_{f_i} − P_i‖² + ω₂ Σ_e v_e² ‖x_{i1} + x_{i2} − x_{i3} − x_{i4}‖² + ω₃ ‖V − V⁰‖²
// by alternating the per-face oriented projection P (eq. 25, with the degenerate fallback
// that prevents flips) and one linear solve with a matrix factored once (eq. 27), the
// alternation Anderson-accelerated unless VertexUpdateOptions::acceleration is 0.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "msmesh/prepared_mesh.h"
#include "msmesh/progress.h"
#include "msmesh/solver.h"

namespace msmesh {

/// Options of Algorithm 2. The defaults are those of preset "cad" (presets.h); ranges and help
/// in vertex_update_parameters() (parameters.h).
struct VertexUpdateOptions {
  double omega1 = 1.0;   ///< ω₁ > 0, normal matching (fixed to 1 in the paper)
  double omega2 = 0.03;  ///< ω₂ ≥ 0, fairness across edges weighted by v² (paper range [0.001, 0.1])
  double omega3 = 0.1;   ///< ω₃ > 0, closeness to the input positions (paper range [0.001, 0.1])
  /// τ ∈ [0, 1]: the share of the fairness term that acts along the surface. The term is
  /// ω₂ v_e² [(n_e·d_e)² + τ ‖d_e − n_e(n_e·d_e)‖²] with d_e = x₁ + x₂ − x₃ − x₄ and n_e the mean
  /// target normal of the edge's two faces: 1 is the paper's ω₂ v_e² ‖d_e‖² (it also moves
  /// vertices along the surface, evening out the triangles), 0 only bends (docs/presets.md,
  /// "Fairness along the normals").
  double fairness_tangential = 1.0;
  int max_iterations = 30;  ///< k ≥ 1
  /// ε₂: stop when the RMS vertex move of an iteration (mean-edge units) is below this. 1e-3:
  /// later iterations move the vertices by less than a thousandth of an edge and change no
  /// printed error figure (docs/presets.md, "Stopping the vertex update"); the paper's is 1e-6.
  double tolerance = 1e-3;
  /// Anderson acceleration of the alternation (src/anderson.h): the next positions combine the
  /// last this-many iterations, which reaches ε₂ in fewer V-steps (docs/presets.md, "Stopping
  /// the vertex update"). 0: the plain alternation of Algorithm 2, as in the paper.
  int acceleration = 5;
  /// Solver of the V-step (ω₁KᵀK + ω₂HᵀH + ω₃I) V = ...; Auto: Cholesky below 40K vertices, CG above.
  LinearSolver solver = LinearSolver::Auto;
  /// Relative residual at which conjugate gradients stop (solver CG); as NormalFilterOptions'.
  double solver_tolerance = 1e-6;
  void validate() const;
};

/// Optional per-vertex multipliers of ω₃ (for inpainting: ≈0 on new vertices, large to pin).
struct VertexUpdateWeights {
  Eigen::VectorXd vertex_omega3;  ///< #V multipliers (empty: all ones)
};

/// How Algorithm 2 ran: iterations, convergence and histories (no per-element arrays).
struct VertexUpdateStats {
  int iterations = 0;
  bool converged = false;
  std::vector<double> change_history;     ///< RMS vertex move per iteration (mean-edge units)
  std::vector<int> solver_iterations;     ///< CG iterations of each V-step (solver CG)
  Eigen::Index fallback_projections = 0;  ///< faces that used the degenerate projection (last iteration)
};

struct VertexUpdateResult : VertexUpdateStats {
  Eigen::MatrixXd V;  ///< #V by 3 new positions
};

/// Updates the vertices of the prepared mesh towards the target unit normals N (#F by 3), with
/// the edge field v (#E: v[e] belongs to mesh.edges().row(e); empty: all ones). The result is
/// in the input's units: invariant to scale, rotation and translation of the input.
VertexUpdateResult update_vertices(const PreparedMesh& mesh, const Eigen::MatrixXd& N, const Eigen::VectorXd& v = {},
                                   const VertexUpdateOptions& options = {}, const VertexUpdateWeights& weights = {},
                                   const ProgressCallback& progress = {});

/// The same for (V, F) (#V by 3, #F by 3), v[e] on build_topology(F).edges.row(e): prepares the
/// mesh (prepared_mesh.h) and forwards.
VertexUpdateResult update_vertices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                   const Eigen::VectorXd& v = {}, const VertexUpdateOptions& options = {},
                                   const VertexUpdateWeights& weights = {}, const ProgressCallback& progress = {});

}  // namespace msmesh
