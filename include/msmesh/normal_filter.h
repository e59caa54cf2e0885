// Algorithm 1 of the paper: NMSTV normal filtering (IRLA + ADMM), DESIGN.md §"Algorithm 1".
//
// Minimises over unit face normals N and the edge discontinuity field v (eq. 15):
//   γ Σ_e v_e² φ(‖(∇N)_e‖) len(e) + β (ε‖∇_E v‖²_W + ‖v − 1‖²_V / (4ε)) + α ‖N − N⁰‖²_U
// with φ(t) = log(1 + ρt)/ρ (NMSTV) or φ(t) = t (MSTV, ref. [11]).
// Lengths are measured in units of the mean edge length (the mesh is normalised inside), so
// the parameters mean the same at any mesh scale.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/prepared_mesh.h"
#include "msmesh/progress.h"
#include "msmesh/solver.h"

namespace msmesh {

/// Options of Algorithm 1. The defaults are those of preset "cad" (presets.h); ranges and help
/// in normal_filter_parameters() (parameters.h).
struct NormalFilterOptions {
  double alpha = 2.5;     ///< α > 0, fidelity to the input normals (eq. 15)
  double beta = 0.02;     ///< β > 0, weight of the Ambrosio–Tortorelli edge term
  double gamma = 2.0;     ///< γ > 0, weight of the (non)convex normal-variation term
  double epsilon = 1e-3;  ///< ε > 0, phase-field width (§5.1)
  double rho = 0.1;  ///< ρ > 0, non-convexity of φ₂ (§5.1 suggests 0.9 for CAD, 0.1 organic; measured: docs/presets.md)
  double penalty = 2.0;       ///< r_p > 0, ADMM penalty (§5.1)
  double relaxation = 1.618;  ///< ν in (0, (1+√5)/2), multiplier step (§5.1)
  int max_iterations = 30;    ///< k ≥ 1 (§5.1)
  double tolerance = 1e-6;    ///< ε₁: stop when ‖N^{k+1} − N^k‖_U < ε₁ (§5.1)
  bool reweight = true;       ///< IRLA weights (NMSTV); false: all w_e = 1 (MSTV)
  double v_initial = 0.0;     ///< v⁰ (Algorithm 1 uses 0)
  /// Project N onto the unit sphere after every N-step (the paper's reading). false: solve the
  /// relaxed problem and project once at the end (stable ADMM; much better at heavy noise).
  bool project_each_iteration = false;
  /// Record the energy (15) after every iteration in NormalFilterResult::energy_history
  /// (costs one extra pass over the edges per iteration).
  bool record_energy = false;
  /// Solver of the N-step (2αS + r GᵀLG) N = ...; Auto: Cholesky below 25K faces, CG above.
  LinearSolver solver = LinearSolver::Auto;
  /// Relative residual at which conjugate gradients stop (solver CG). 1e-6: the error figures
  /// of a denoise agree with those at 1e-8 (and with the Cholesky path) to four digits, in a
  /// third fewer sweeps (docs/performance.md, "Solver tolerance"); 1e-8 for exact comparisons.
  double solver_tolerance = 1e-6;
  /// λ ≥ 0 of the polish after the last iteration (src/normal_polish.h): one implicit step of a
  /// joint bilateral filter guided by the filtered normals and masked by v, which flattens the
  /// noise the fidelity term leaves on flat and smoothly curved parts. 0: none, as the paper;
  /// preset cad 3 (docs/presets.md, "The polish").
  double polish = 3.0;
  /// σ > 0 of the polish's range weight exp(−‖N_i − N_j‖² / 2σ²): normals further apart than
  /// about 2σ (a crease of ~35° at 0.3) are not averaged.
  double polish_range = 0.3;
  /// Throws InvalidInput naming the parameter, its value and the valid range.
  void validate() const;
};

/// Optional spatially varying weights (for inpainting): empty vectors mean "all ones".
struct NormalFilterWeights {
  Eigen::VectorXd face_alpha;  ///< #F multipliers of α (fidelity per face)
  Eigen::VectorXd edge_beta;   ///< #E multipliers of β in the ‖v − 1‖² term, in the order of Topology::edges
};

/// How Algorithm 1 ran: iterations, convergence and histories (no per-element arrays).
struct NormalFilterStats {
  int iterations = 0;
  bool converged = false;                ///< stopped by the tolerance rather than max_iterations
  std::vector<double> residual_history;  ///< ‖p − ∇N‖_V per iteration (mean-edge units)
  std::vector<double> change_history;    ///< ‖N^{k+1} − N^k‖_U per iteration
  std::vector<double> energy_history;    ///< energy (15) per iteration (when record_energy)
  std::vector<int> v_solver_iterations;  ///< CG iterations of each v-step
  std::vector<int> n_solver_iterations;  ///< CG iterations of each N-step (solver CG)
};

struct NormalFilterResult : NormalFilterStats {
  Eigen::MatrixXd normals;  ///< #F by 3 filtered unit face normals
  Eigen::VectorXd v;        ///< #E edge field (≈0 on features, ≈1 elsewhere): v[e] belongs to edges.row(e)
  Eigen::MatrixXi edges;    ///< #E by 2 vertex indices of the edges v refers to (Topology::edges)
};

/// Filters the face normals of the prepared mesh. `normals0` (#F by 3) are the input normals
/// N⁰; when empty, the face normals of the mesh are used. Throws InvalidInput for bad options
/// or a mesh without faces, SolverError when a factorisation fails, Cancelled when `progress`
/// returns false.
NormalFilterResult filter_normals(const PreparedMesh& mesh, const NormalFilterOptions& options = {},
                                  const NormalFilterWeights& weights = {}, const ProgressCallback& progress = {},
                                  const Eigen::MatrixXd& normals0 = {});

/// The same for (V, F) (#V by 3, #F by 3): prepares the mesh (prepared_mesh.h) and forwards.
NormalFilterResult filter_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                  const NormalFilterOptions& options = {}, const NormalFilterWeights& weights = {},
                                  const ProgressCallback& progress = {}, const Eigen::MatrixXd& normals0 = {});

/// Energy (15) of normals N (#F by 3) and edge field v (#E, v[e] on Topology::edges.row(e)) for the mesh (V, F), in the
/// same normalised units as filter_normals (for tests and reports).
double nmstv_energy(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                    const Eigen::VectorXd& v, const Eigen::MatrixXd& normals0, const NormalFilterOptions& options);

}  // namespace msmesh
