// Choice of linear solver for the constant systems of Algorithms 1 and 2.
#pragma once

namespace msmesh {

/// How the systems that stay fixed over the iterations (the N-step of Algorithm 1, the
/// V-step of Algorithm 2) are solved. Both give the same result to the solver tolerance
/// (about 1e-10 relative); they differ in speed and memory (docs/performance.md).
enum class LinearSolver {
  Auto,      ///< factorisation below ~25K faces, CG above (measured crossover, docs/performance.md)
  Cholesky,  ///< factor once with CHOLMOD, then two triangular solves per iteration
  CG,        ///< Jacobi-preconditioned conjugate gradients warm-started from the last iterate
};

}  // namespace msmesh
