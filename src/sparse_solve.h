// Internal: the factor-once sparse Cholesky used by the fixed systems (N-step, vertex update).
//
// CHOLMOD's simplicial LLᵀ (SuiteSparse) measured 2.3× faster than Eigen's SimplicialLLT for
// the 30 three-column solves on the 61K-face Cone, with the same factorisation time; the
// supernodal variant was slower on these very sparse mesh matrices (docs/performance.md).
#pragma once
#include <Eigen/CholmodSupport>
#include <memory>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/operators.h"
#include "pcg.h"
#include "tree_solve.h"

namespace msmesh::detail {

class FixedCholesky {
 public:
  FixedCholesky(const SparseMatrix& A, const std::string& what) {
    chol_.compute(A);
    if (chol_.info() != Eigen::Success)
      throw SolverError(what + ": Cholesky factorisation failed (matrix not positive definite)");
    tree_ = TreeSolve(chol_.factor());
  }
  /// Share of the factor's entries whose solves run on two threads (tree_solve.h).
  double parallel_share() const { return tree_.valid() ? tree_.parallel_share() : 0.0; }
  /// Solves A X = B (three columns, row-major); X may be B.
  void solve(const RowMatrixX3& B, RowMatrixX3& X, const std::string& what) const {
    if (tree_.valid()) {
      tree_.solve(B, X);
    } else {
      X = chol_.solve(Eigen::MatrixXd(B));
      if (chol_.info() != Eigen::Success) throw SolverError(what + ": solve failed");
    }
    if (!X.allFinite()) throw SolverError(what + ": solve failed (non-finite result)");
  }

 private:
  // Eigen's wrapper, with access to CHOLMOD's factor for the triangular solves.
  struct Factor : Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> {
    const cholmod_factor* factor() const { return m_cholmodFactor; }
  };
  Factor chol_;
  TreeSolve tree_{nullptr};
};

/// A system A X = B that stays the same over the iterations (N-step, vertex update), solved
/// by factoring once or by warm-started conjugate gradients (pcg.h); callers pick which.
class ConstantSystem {
 public:
  ConstantSystem(const SparseMatrix& A, bool conjugate_gradients, std::string what) : what_(std::move(what)) {
    if (conjugate_gradients)
      pcg_ = std::make_unique<BlockPcg>(A);
    else
      chol_ = std::make_unique<FixedCholesky>(A, what_);
  }
  /// Solves A X = B; X holds the warm start for CG. Returns the CG sweeps, or −1 when the
  /// system was factored. Throws SolverError naming the system.
  int solve(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance) const {
    if (pcg_) return pcg_->solve(B, X, relative_tolerance, 100000, what_).iterations;
    chol_->solve(B, X, what_);
    return -1;
  }
  bool iterative() const { return pcg_ != nullptr; }

 private:
  std::string what_;
  std::unique_ptr<FixedCholesky> chol_;
  std::unique_ptr<BlockPcg> pcg_;
};

}  // namespace msmesh::detail
