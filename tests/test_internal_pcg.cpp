// The library's conjugate gradients (src/pcg.h) on one column, as the v-step uses them.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "msmesh/errors.h"
#include "pcg.h"

using namespace msmesh;

TEST(InternalPcg, OneColumnSolvesWithAChangedDiagonal) {
  // A path-graph Laplacian plus a diagonal, set after construction.
  const int n = 50;
  Eigen::SparseMatrix<double> A(n, n);
  for (int i = 0; i < n; ++i) {
    A.insert(i, i) = 0.0;  // stored, replaced below
    if (i > 0) A.insert(i, i - 1) = -1.0;
    if (i + 1 < n) A.insert(i, i + 1) = -1.0;
  }
  A.makeCompressed();
  for (bool reorder : {false, true}) {
    detail::BlockPcg pcg(A, reorder);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    EXPECT_THROW(pcg.solve(b, x, 1e-10, 1000, "test"), SolverError);  // zero diagonal
    const Eigen::VectorXd d = Eigen::VectorXd::Constant(n, 3.0);
    pcg.set_diagonal(d);
    const detail::PcgStats st = pcg.solve(b, x, 1e-10, 1000, "test");
    Eigen::SparseMatrix<double> Ad = A;
    for (int i = 0; i < n; ++i) Ad.coeffRef(i, i) = 3.0;
    EXPECT_LT((Ad * x - b).norm(), 1e-9 * b.norm());
    EXPECT_GT(st.iterations, 0);
    EXPECT_EQ(pcg.solve(b, x, 1e-10, 1000, "test").iterations, 0);  // warm start: done
  }
}
