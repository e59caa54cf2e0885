// Internal: the factor-once sparse Cholesky used by the fixed systems (N-step, vertex update).
//
// CHOLMOD's simplicial LLᵀ (SuiteSparse) measured 2.3× faster than Eigen's SimplicialLLT for
// the 30 three-column solves on the 61K-face Cone, with the same factorisation time; the
// supernodal variant was slower on these very sparse mesh matrices (docs/performance.md).
#pragma once
#include <Eigen/CholmodSupport>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/operators.h"

namespace msmesh::detail {

class FixedCholesky {
 public:
  FixedCholesky(const SparseMatrix& A, const std::string& what) {
    chol_.compute(A);
    if (chol_.info() != Eigen::Success)
      throw SolverError(what + ": Cholesky factorisation failed (matrix not positive definite)");
  }
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B, const std::string& what) const {
    Eigen::MatrixXd X = chol_.solve(B);
    if (chol_.info() != Eigen::Success || !X.allFinite()) throw SolverError(what + ": solve failed");
    return X;
  }

 private:
  Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> chol_;
};

}  // namespace msmesh::detail
