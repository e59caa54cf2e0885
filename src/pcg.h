// Internal: Jacobi-preconditioned conjugate gradients for the constant SPD systems, several
// right-hand sides at once (the three coordinates of the N-step or the vertex update).
//
// Why: the N-step matrix 2αS + r GᵀLG is a face-graph Laplacian plus a positive diagonal, so
// its condition number is bounded independently of the mesh size (κ ≈ 1 + 3r/(α·area) in mean
// edge units): warm-started from the previous iterate, CG needs a bounded number of sweeps
// and the cost grows linearly with the face count, where a sparse Cholesky factor grows like
// n^1.5 (docs/performance.md has the measurements).
//
// Chebyshev iteration (use_chebyshev) replaces CG where the spectrum is known: the N-step's
// constant matrix after its first solve, the v-step's diagonally dominant one throughout; one
// pass over the rows per sweep instead of three (docs/performance.md, "Issue 20, sixth round").
//
// Deterministic whatever the thread count: the matrix–vector products are row-parallel and
// every reduction sums fixed blocks of rows in a fixed order. And whatever the processor: where
// it has AVX, three-column solves keep their work vectors in rows of four and run the hot loops
// four columns per instruction (wide_rows.h), the same operations in the same order.
//
// Storage: BlockPcg keeps the matrix and its work vectors in double precision;
// SingleBlockPcg keeps the matrix values, the preconditioner and the work vectors r, p, q in
// single precision (~40 % fewer bytes per sweep; a third less time in the N-step's sweeps at
// 1.3M faces) while every product, sum and the iterate x stay in double. q is A p of the stored p, and x moves
// along the same stored p, so the updated residual follows b − A x; what single precision
// changes is the matrix itself, by one rounding of each entry (relative 6e-8): the solution is
// that of a matrix within κ·6e-8 of A, far inside the N-step's tolerance (docs/performance.md).
// Chebyshev iteration stores its correction x − x₀ and first residual in that precision (their
// rounding is relative to the residual the solve starts from). Used for the N-step under CG.
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <string>
#include <vector>

#include "default_init_allocator.h"

namespace msmesh::detail {

using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
using RowMatrixX3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// A symmetric matrix with at most three entries beside the diagonal in each row (a face
/// graph's), given row by row instead of assembled: row(i, diag, cols, vals) writes row i's
/// diagonal entry into *diag and its other entries (column numbers, any order; a repeated
/// column is summed) into cols and vals, and returns their number: at most three (a row of
/// more is refused; cols and vals have room for kFixedWidthRoom). Called for several rows at
/// once from the library's threads.
using FixedWidthRows = std::function<int(Eigen::Index row, double* diag, int* cols, double* vals)>;
constexpr int kFixedWidthRoom = 8;

struct PcgStats {
  int iterations = 0;              ///< sweeps of the slowest column
  double relative_residual = 0.0;  ///< max over the columns of ‖b − Ax‖ / ‖b‖
};

/// Jacobi-preconditioned CG on a sparse SPD matrix, for 3 right-hand sides at once (the
/// constant N-step and vertex systems) or one (the v-step, whose diagonal changes between
/// solves: set_diagonal). The one CG of the library; `Stored` is the precision of the matrix
/// and the work vectors (double or float, see above).
template <class Stored>
class BasicBlockPcg {
 public:
  /// `A` must be symmetric positive definite with a positive diagonal, every diagonal entry
  /// stored. `reorder`: work in reverse Cuthill–McKee order (pays off over many sweeps; costs
  /// a permutation of B and X per solve).
  explicit BasicBlockPcg(const Eigen::SparseMatrix<double>& A, bool reorder = true);
  /// The same, taking over A's arrays when there is no reordering and A is compressed with
  /// its columns sorted within each row and Stored is double (no copy of the matrix: the
  /// v-step's is the largest array of the normal filter; it keeps the compressed layout);
  /// otherwise as above.
  explicit BasicBlockPcg(Eigen::SparseMatrix<double>&& A, bool reorder);
  /// The same in a given order (position i holds original row order[i], a permutation of the
  /// rows; empty: the rows' own): for a matrix with the pattern of one whose reverse
  /// Cuthill–McKee order is already known (the polish's, the N-step's).
  BasicBlockPcg(const Eigen::SparseMatrix<double>& A, std::vector<int> order);
  /// The n by n matrix of `rows`, straight into the fixed-width layout below (no compressed
  /// matrix, no copy of it: the same products, bit for bit, as from the assembled matrix), in
  /// `order` (position i holds row order[i]) or, when that is empty, in the rows' reverse
  /// Cuthill–McKee order. Throws SolverError when a row has more than three entries.
  BasicBlockPcg(Eigen::Index n, const FixedWidthRows& rows, std::vector<int> order);
  /// Replaces the diagonal of A by d (#rows, original order).
  void set_diagonal(const Eigen::VectorXd& d);
  /// Solves A X = B (n by 3) in place, X holding the warm start. Stops when every column's
  /// residual is below `relative_tolerance` × ‖b‖ (or exactly 0). Throws SolverError naming
  /// `what` when `max_iterations` do not suffice, the numbers stop being finite or the
  /// diagonal is not positive.
  PcgStats solve(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance, int max_iterations,
                 const std::string& what) const;
  /// The same for one right-hand side b (n), x holding the warm start.
  PcgStats solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double relative_tolerance, int max_iterations,
                 const std::string& what) const;
  /// Solve by Chebyshev iteration once the spectrum of D⁻¹A is known: one pass over the rows
  /// per sweep instead of CG's three, for a few more sweeps. The upper end of the spectrum
  /// comes from the matrix (Gershgorin), the lower one too when the matrix is strongly
  /// diagonally dominant (the v-step's; recomputed by set_diagonal), else from the Lanczos
  /// coefficients of the first CG solve of at least kLanczosSweeps sweeps (the N-step's).
  /// CG takes over a solve that does not converge at the promised rate (and learns the
  /// spectrum again). `gershgorin_lower`: the lower end from Gershgorin whatever the ratio of
  /// the ends, for a single solve that has no CG solve before it to learn from (the polish's
  /// I + Laplacian, where Gershgorin's 1/max_i a_ii is also the bound that A ≥ I gives).
  void use_chebyshev(bool gershgorin_lower = false);
  /// The order CG works in: position i holds original row order()[i]; empty when the rows
  /// keep their order.
  const std::vector<int>& order() const { return perm_; }
  /// As solve, with B and X already in order() (no permutation in and out): for callers
  /// that keep their iterates in that order across many solves.
  PcgStats solve_in_order(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance, int max_iterations,
                          const std::string& what) const;
  Eigen::Index size() const { return static_cast<Eigen::Index>(inv_diag_.size()); }

 private:
  template <int K, class M>
  PcgStats solve_reordered(const M& B, M& X, double relative_tolerance, int max_iterations,
                           const std::string& what) const;
  template <int K>
  PcgStats solve_permuted(const double* B, double* X, double relative_tolerance, int max_iterations,
                          const std::string& what) const;
  // S: the stride of the work vectors' rows, K or, for the wide rows (wide_rows.h), 4.
  template <int K, bool Ell, int S>
  PcgStats solve_layout(const double* B, double* X, double relative_tolerance, int max_iterations,
                        const std::string& what) const;
  template <int K, bool Ell, int S>
  PcgStats solve_chebyshev(const double* B, double* X, double relative_tolerance, int max_iterations,
                           const std::string& what) const;
  // a = (A v)_i, v with rows of stride S.
  template <int K, int S, bool Ell, class T>
  void row_product(Eigen::Index i, const T* __restrict v, double* a) const;
  // A product pass's rows as simple rows for the parallel threshold (parallel.h): compressed
  // rows of many entries (the vertex update's ~19) are worth several.
  template <bool Ell>
  Eigen::Index product_weight() const {
    if constexpr (Ell) return 1;
    return std::max<Eigen::Index>(1, A_.nonZeros() / std::max<Eigen::Index>(1, 4 * A_.rows()));
  }
  void learn_spectrum(const std::vector<double>& alpha, const std::vector<double>& beta) const;
  void set_spectrum(double radius);
  void check_diagonal() const;
  void init(const Eigen::SparseMatrix<double>& A, bool reorder, std::vector<int> order = {});
  void note_bad_diagonal(Eigen::Index i, double d);
  void find_diagonal();
  void to_fixed_width();
  std::vector<int> perm_;          // reverse Cuthill–McKee: position i holds original row perm_[i]; empty: none
  std::vector<int> diag_pos_;      // index of row i's diagonal entry in A_'s values
  Eigen::SparseMatrix<Stored> A_;  // P A Pᵀ; symmetric, so its columns are read as its rows
  // P A Pᵀ in a fixed-width layout when no row has more than kEllWidth entries beside the
  // diagonal (a face graph: three neighbours): row i is ell_diag_[i] and the entries
  // ell_vals_[kEllWidth i + k] at columns ell_cols_[...] (unused: 0 at column i). A product
  // then runs without a loop of unknown length per row: 1.4x faster than the compressed rows
  // in single precision, 1.15x in double (docs/performance.md); A_ is emptied.
  static constexpr int kEllWidth = 3;
  UninitializedVector<int> ell_cols_;  // (every entry written in parallel)
  UninitializedVector<Stored> ell_vals_, ell_diag_;
  Eigen::Matrix<Stored, Eigen::Dynamic, 1> inv_diag_;
  // Chebyshev iteration (use_chebyshev): the interval of D⁻¹A's spectrum; λ_min_ 0 until
  // learnt from a CG solve of at least kLanczosSweeps sweeps.
  static constexpr int kLanczosSweeps = 8;
  static constexpr double kGershgorinKappa = 1.1;
  UninitializedVector<float> off_sums_;  // Σ_{j≠i} |a_ij| per row (use_chebyshev)
  bool chebyshev_ = false;
  bool gershgorin_lower_ = false;  // use_chebyshev's argument
  double lambda_max_ = 0;
  mutable double lambda_min_ = 0;
  Eigen::Index bad_row_ = -1;  // a row (original order) whose diagonal is not positive, or -1
  double bad_value_ = 0;
  // Work space, n by K row-major (not thread-safe: one solve at a time).
  // Written in full by each solve's first passes, on the library's threads
  // (default_init_allocator.h: no serial zeroing of fresh pages).
  mutable UninitializedVector<Stored> R_, P_, Q_;
  mutable UninitializedVector<double> Bp_, Xp_;
};

using BlockPcg = BasicBlockPcg<double>;
using SingleBlockPcg = BasicBlockPcg<float>;
extern template class BasicBlockPcg<double>;
extern template class BasicBlockPcg<float>;

/// Copies between Eigen's default column-major #rows by 3 matrices and the row-major layout.
RowMatrixX3 to_rows(const Eigen::MatrixXd& M);

}  // namespace msmesh::detail
