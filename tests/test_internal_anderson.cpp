// Anderson acceleration (src/anderson.h) of a fixed-point iteration x ← G(x): on a linear
// contraction it reaches the fixed point of the plain iteration, in far fewer steps; without
// history it is the plain iteration; a restart forgets the history.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "anderson.h"

using namespace msmesh;
using detail::RowMatrixX3;

namespace {

// G(x) = M x + b with M symmetric, eigenvalues in [0.05, 0.95] (a contraction, like the vertex
// update's alternation near its fixed point): the fixed point solves (I − M) x = b.
struct Contraction {
  Eigen::MatrixXd M;
  RowMatrixX3 b;
  explicit Contraction(int n) {
    const Eigen::MatrixXd Q = Eigen::MatrixXd::Random(n, n).householderQr().householderQ();
    const Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(n, 0.05, 0.95);
    M = Q * lambda.asDiagonal() * Q.transpose();
    b = RowMatrixX3::Random(n, 3);
  }
  RowMatrixX3 operator()(const RowMatrixX3& x) const { return M * x + b; }
  RowMatrixX3 fixed_point() const {
    return (Eigen::MatrixXd::Identity(M.rows(), M.cols()) - M).partialPivLu().solve(Eigen::MatrixXd(b));
  }
};

// Steps until ‖G(x) − x‖ < tol (at most max_steps); x ends at the last G(x).
int iterate(const Contraction& G, detail::AndersonAcceleration* aa, RowMatrixX3& x, double tol, int max_steps) {
  for (int k = 1; k <= max_steps; ++k) {
    const RowMatrixX3 g = G(x);
    if ((g - x).norm() < tol) {
      x = g;
      return k;
    }
    if (aa)
      aa->step(g, x);
    else
      x = g;
  }
  return max_steps + 1;
}

}  // namespace

TEST(InternalAnderson, ReachesThePlainIterationsFixedPointInFarFewerSteps) {
  const Contraction G(40);
  const RowMatrixX3 truth = G.fixed_point();
  RowMatrixX3 plain = RowMatrixX3::Zero(40, 3), fast = RowMatrixX3::Zero(40, 3);
  detail::AndersonAcceleration aa(5);
  const int plain_steps = iterate(G, nullptr, plain, 1e-10, 2000);
  const int fast_steps = iterate(G, &aa, fast, 1e-10, 2000);
  EXPECT_LT((plain - truth).norm(), 1e-8);
  EXPECT_LT((fast - truth).norm(), 1e-8);
  EXPECT_GT(plain_steps, 300);             // 0.95^k < 1e-11 takes ~490 steps
  EXPECT_LT(fast_steps, plain_steps / 3);  // measured: 432 against 90 at depth 5
}

TEST(InternalAnderson, WithoutHistoryItIsThePlainStep) {
  const Contraction G(10);
  RowMatrixX3 x = RowMatrixX3::Random(10, 3);
  const RowMatrixX3 g = G(x);
  detail::AndersonAcceleration aa(3);
  aa.step(g, x);  // the first step has no history
  EXPECT_EQ(x, g);
  const RowMatrixX3 g2 = G(x);
  aa.step(g2, x);  // now one difference: not the plain step
  EXPECT_GT((x - g2).norm(), 1e-12);
  aa.restart();
  const RowMatrixX3 g3 = G(x);
  aa.step(g3, x);  // history forgotten: plain again
  EXPECT_EQ(x, g3);
}

TEST(InternalAnderson, SolvesALinearFixedPointExactlyOnceTheHistorySpansIt) {
  // With depth ≥ n the combination is GMRES on (I − M) x = b: exact after n + 1 steps (to
  // round-off), far before the plain iteration.
  const Contraction G(6);
  RowMatrixX3 x = RowMatrixX3::Zero(6, 3);
  detail::AndersonAcceleration aa(8);
  for (int k = 0; k < 8; ++k) aa.step(G(x), x);
  EXPECT_LT((x - G.fixed_point()).norm(), 1e-9);
}
