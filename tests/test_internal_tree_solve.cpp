// The factorisation and triangular solves split over the elimination tree (src/cholesky.cpp,
// src/tree_solve.h) against CHOLMOD's own factorisation and solve, on systems large enough
// to be split and too small to be.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <vector>

#include "sparse_build.h"
#include "sparse_solve.h"
#include "tree_solve.h"

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace msmesh;
using namespace msmesh::detail;

namespace {

// Graph Laplacian of an n×n grid with both diagonals of every cell (like the vertex-update
// matrix: a 2-D mesh graph with extra couplings) plus c·I: symmetric positive definite.
SparseMatrix grid_matrix(int n, double c) {
  auto id = [n](int i, int j) { return i * n + j; };
  return symmetric_from_rows(
      static_cast<Eigen::Index>(n) * n, [](Eigen::Index) { return 9; },
      [&](Eigen::Index r, int* col, double* val) {
        const int i = static_cast<int>(r) / n, j = static_cast<int>(r) % n;
        int k = 1;
        double diag = c;
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj) {
            if ((di == 0 && dj == 0) || i + di < 0 || i + di >= n || j + dj < 0 || j + dj >= n) continue;
            const double w = (di == 0 || dj == 0) ? 1.0 : 0.5;
            col[k] = id(i + di, j + dj);
            val[k++] = -w;
            diag += w;
          }
        col[0] = static_cast<int>(r);
        val[0] = diag;
        return k;
      });
}

RowMatrixX3 rhs(Eigen::Index n) {
  RowMatrixX3 B(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) B(i, c) = std::sin(0.37 * static_cast<double>(i) + c) + 0.1 * c;
  return B;
}

double relative_residual(const SparseMatrix& A, const RowMatrixX3& X, const RowMatrixX3& B) {
  return (A * Eigen::MatrixXd(X) - Eigen::MatrixXd(B)).norm() / Eigen::MatrixXd(B).norm();
}

}  // namespace

TEST(TreeSolve, LargeSystemIsSplitAndMatchesCholmod) {
  const SparseMatrix A = grid_matrix(200, 0.05);  // 40K rows, L with ~2M entries
  FixedCholesky chol(A, "test");
  Eigen::CholmodSimplicialLLT<SparseMatrix, Eigen::Lower> reference(A);
  ASSERT_EQ(reference.info(), Eigen::Success);
  const RowMatrixX3 B = rhs(A.rows());
  RowMatrixX3 X;
  chol.solve(B, X, "test");
  const Eigen::MatrixXd Xref = reference.solve(Eigen::MatrixXd(B));
  EXPECT_LT((Eigen::MatrixXd(X) - Xref).norm() / Xref.norm(), 1e-12);
  EXPECT_LT(relative_residual(A, X, B), 1e-12);

  // The split is a property of the factor: a real one here, and the same bits on 1 thread.
  TreeSolve tree(nullptr);
  EXPECT_FALSE(tree.valid());
#ifdef _OPENMP
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const FixedCholesky chol1(A, "test");  // factored and solved on one thread
  RowMatrixX3 one;
  chol1.solve(B, one, "test");
  omp_set_num_threads(std::max(2, threads));
  RowMatrixX3 two;
  chol.solve(B, two, "test");
  omp_set_num_threads(threads);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, X);
#endif
  // Solving in place (X = B) gives the same.
  RowMatrixX3 inplace = B;
  chol.solve(inplace, inplace, "test");
  EXPECT_EQ(inplace, X);
}

TEST(TreeSolve, SplitCoversMostOfTheFactorOnMeshLikeGraphs) {
  const SparseMatrix A = grid_matrix(200, 0.05);
  const FixedCholesky chol(A, "test");
  EXPECT_GT(chol.parallel_share(), 0.7);  // at most 30 % of L in the serial top of the tree
  EXPECT_GT(chol.parallel_factor_share(), 0.6);
  RowMatrixX3 X;
  const RowMatrixX3 B = rhs(A.rows());
  chol.solve(B, X, "test");
  EXPECT_LT(relative_residual(A, X, B), 1e-12);
}

TEST(TreeSolve, SmallSystemStaysSerialAndMatches) {
  const SparseMatrix A = grid_matrix(20, 0.5);  // 400 rows
  FixedCholesky chol(A, "test");
  EXPECT_EQ(chol.parallel_share(), 0.0);
  EXPECT_EQ(chol.parallel_factor_share(), 0.0);
  const RowMatrixX3 B = rhs(A.rows());
  RowMatrixX3 X;
  chol.solve(B, X, "test");
  EXPECT_LT(relative_residual(A, X, B), 1e-13);
}

TEST(TreeSolve, NonFiniteRightHandSideIsAnError) {
  const SparseMatrix A = grid_matrix(10, 0.5);
  FixedCholesky chol(A, "the test system");
  RowMatrixX3 B = rhs(A.rows()), X;
  B(7, 1) = std::numeric_limits<double>::quiet_NaN();
  try {
    chol.solve(B, X, "the test system");
    FAIL() << "no error";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("the test system"), std::string::npos) << e.what();
  }
}

TEST(TreeSolve, NotPositiveDefiniteIsAnErrorNamingTheSystem) {
  SparseMatrix A = grid_matrix(60, 0.5);  // large enough for the split factorisation
  A.coeffRef(1234, 1234) = -5.0;
  try {
    FixedCholesky chol(A, "the test system");
    FAIL() << "no error";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("the test system"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
}
