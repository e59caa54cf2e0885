// Internal: the factor-once sparse Cholesky used by the fixed systems (N-step, vertex update).
//
// CHOLMOD's simplicial LLᵀ (SuiteSparse) measured 2.3× faster than Eigen's SimplicialLLT for
// the 30 three-column solves on the 61K-face Cone, with the same factorisation time; the
// supernodal variant was slower on these very sparse mesh matrices (docs/performance.md).
// CHOLMOD itself stays inside cholesky.cpp.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/operators.h"
#include "pcg.h"

namespace msmesh::detail {

/// A sparse Cholesky factorisation A = L Lᵀ (CHOLMOD simplicial, fill-reducing ordering by
/// CHOLMOD's default: AMD), computed once; solves three right-hand sides at a time. The
/// numeric factorisation and the solves run two sets of subtrees of the elimination tree at
/// once (tree_solve.h); the factor is the same bits as a serial factorisation.
class FixedCholesky {
 public:
  /// Factors the symmetric positive definite A (lower triangle used); throws SolverError
  /// naming `what` when it is not positive definite.
  FixedCholesky(const SparseMatrix& A, const std::string& what);
  ~FixedCholesky();
  FixedCholesky(const FixedCholesky&) = delete;
  FixedCholesky& operator=(const FixedCholesky&) = delete;
  /// Share of the factor's entries whose solves run on two threads.
  double parallel_share() const;
  /// Share of the factorisation work done on two threads.
  double parallel_factor_share() const;
  /// Solves A X = B (three columns, row-major); X may be B. Not for two solves at once on
  /// the same object (shared work space).
  void solve(const RowMatrixX3& B, RowMatrixX3& X, const std::string& what) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A solver tolerance at or above this lets the iterative solvers of the normal filter and the
/// vertex update work loosely where the result allows it (the N-step in single precision, early
/// N- and V-steps inexact); below it (preset paper's 1e-8, exact comparisons) every solve is in
/// double precision and reaches the tolerance.
constexpr double kLooseSolvesFromTolerance = 1e-6;

/// A system A X = B that stays the same over the iterations (N-step, vertex update), solved
/// by factoring once or by warm-started conjugate gradients (pcg.h); callers pick which, and
/// for CG whether the matrix and work vectors are stored in single precision (CgSingle, the
/// N-step: after its first solve, Chebyshev iteration on the spectrum that solve learnt).
class ConstantSystem {
 public:
  enum class Method { Cholesky, Cg, CgSingle };
  ConstantSystem(const SparseMatrix& A, Method method, std::string what) : what_(std::move(what)) {
    if (method == Method::Cg) {
      pcg_ = std::make_unique<BlockPcg>(A);
    } else if (method == Method::CgSingle) {
      pcg_single_ = std::make_unique<SingleBlockPcg>(A);
      pcg_single_->use_chebyshev();
    } else {
      chol_ = std::make_unique<FixedCholesky>(A, what_);
    }
  }
  /// The same for CG (Method Cg or CgSingle) on the n by n matrix of fixed-width `rows`
  /// (pcg.h), never assembled; in `order` (empty: the rows' reverse Cuthill–McKee order).
  ConstantSystem(Eigen::Index n, const FixedWidthRows& rows, std::vector<int> order, Method method, std::string what)
      : what_(std::move(what)) {
    if (method == Method::Cg) {
      pcg_ = std::make_unique<BlockPcg>(n, rows, std::move(order));
    } else if (method == Method::CgSingle) {
      pcg_single_ = std::make_unique<SingleBlockPcg>(n, rows, std::move(order));
      pcg_single_->use_chebyshev();
    } else {
      throw SolverError(what_ + ": a factorisation needs the assembled matrix");
    }
  }
  /// The same for CG in double precision on a matrix A already in the order to work in (no
  /// reordering): A's arrays are taken over when its columns are sorted within each row.
  ConstantSystem(SparseMatrix&& A, std::string what) : what_(std::move(what)) {
    pcg_ = std::make_unique<BlockPcg>(std::move(A), /*reorder=*/false);
  }
  /// Solves A X = B; X holds the warm start for CG. Returns the CG sweeps, or −1 when the
  /// system was factored. Throws SolverError naming the system.
  int solve(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance) const {
    if (pcg_) return pcg_->solve(B, X, relative_tolerance, kMaxSweeps, what_).iterations;
    if (pcg_single_) return pcg_single_->solve(B, X, relative_tolerance, kMaxSweeps, what_).iterations;
    chol_->solve(B, X, what_);
    return -1;
  }
  bool iterative() const { return chol_ == nullptr; }
  /// The row order solve_in_order works in (position i holds original row order()[i]);
  /// empty when it is the original order.
  const std::vector<int>& order() const {
    return pcg_ ? pcg_->order() : (pcg_single_ ? pcg_single_->order() : no_order_);
  }
  /// As solve, with B and X in order() (no permutation in and out per solve).
  int solve_in_order(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance) const {
    if (pcg_) return pcg_->solve_in_order(B, X, relative_tolerance, kMaxSweeps, what_).iterations;
    if (pcg_single_) return pcg_single_->solve_in_order(B, X, relative_tolerance, kMaxSweeps, what_).iterations;
    chol_->solve(B, X, what_);
    return -1;
  }

 private:
  static constexpr int kMaxSweeps = 100000;
  std::string what_;
  std::unique_ptr<FixedCholesky> chol_;
  std::unique_ptr<BlockPcg> pcg_;
  std::unique_ptr<SingleBlockPcg> pcg_single_;
  std::vector<int> no_order_;
};

}  // namespace msmesh::detail
