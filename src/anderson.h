// Internal: Anderson acceleration (type II, Walker & Ni 2011; for local/global geometry solvers,
// Peng et al. 2018) of a fixed-point iteration x ← G(x) on #rows by 3 arrays.
//
// Given the current iterate x_k and its image g_k = G(x_k), the next iterate is
//   x_{k+1} = g_k − Σ_j θ_j Δg_j,   θ = argmin ‖f_k − Σ_j θ_j Δf_j‖,
// with f = g − x the residuals and Δ the differences of the last `depth` consecutive pairs. On a
// linear contraction this is GMRES on the fixed-point equation; the plain iteration x_{k+1} =
// g_k is the case of no history. The inner products add fixed blocks in a fixed order, so the
// iterates do not depend on the number of threads.
#pragma once
#include <vector>

#include "pcg.h"

namespace msmesh::detail {

class AndersonAcceleration {
 public:
  /// depth ≥ 1: how many differences of earlier iterations are combined.
  explicit AndersonAcceleration(int depth) : depth_(depth) {}
  /// x holds x_k on entry and x_{k+1} on return; g = G(x_k). The history's arrays are allocated
  /// as they are first needed (an iteration that stops early allocates none).
  void step(const RowMatrixX3& g, RowMatrixX3& x);
  /// Forgets the history: the next step is a plain one (after the residual grew, say).
  void restart() {
    count_ = next_ = 0;
    has_previous_ = false;
  }

 private:
  int depth_;
  int count_ = 0, next_ = 0;  ///< differences held, and the ring slot the next one goes to
  bool has_previous_ = false;
  std::vector<RowMatrixX3> df_, dg_;  ///< ring of Δf and Δg
  RowMatrixX3 f_previous_, g_previous_;
};

}  // namespace msmesh::detail
