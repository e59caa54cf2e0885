// symmetric_from_rows (src/sparse_build.h) against a dense accumulation, for short rows
// (sorted in place), long rows with few distinct columns (slot map) and long rows with many
// (a high-valence vertex: sorted as pairs).
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "sparse_build.h"

using namespace msmesh::detail;

TEST(SparseBuild, RowsWithRepeatsMatchADenseSum) {
  const Eigen::Index n = 300;
  // Row i lists columns (i * 7 + k * k) % n for k < len(i), value k + 1 (with many repeats);
  // symmetric by construction: we add each (i, j) pair to both rows.
  auto entries = [&](Eigen::Index i) {
    std::vector<std::pair<int, double>> e;
    const int len = i % 3 == 0 ? 6 : (i % 3 == 1 ? 90 : 400);  // short, long few, long many
    const int spread = i % 3 == 1 ? 12 : 120;
    for (int k = 0; k < len; ++k) e.push_back({static_cast<int>((i + (k * 37) % spread) % n), 0.5 + k % 5});
    return e;
  };
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  std::vector<std::vector<std::pair<int, double>>> rows(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    for (const auto& [j, v] : entries(i)) {
      rows[static_cast<size_t>(i)].push_back({j, v});
      if (j != i) rows[static_cast<size_t>(j)].push_back({static_cast<int>(i), v});
      dense(i, j) += v;
      if (j != i) dense(j, i) += v;
    }
  const Eigen::SparseMatrix<double> A = symmetric_from_rows(
      n, [&](Eigen::Index i) { return static_cast<Eigen::Index>(rows[static_cast<size_t>(i)].size()); },
      [&](Eigen::Index i, int* col, double* val) {
        int m = 0;
        for (const auto& [j, v] : rows[static_cast<size_t>(i)]) {
          col[m] = j;
          val[m++] = v;
        }
        return m;
      });
  EXPECT_LT((Eigen::MatrixXd(A) - dense).cwiseAbs().maxCoeff(), 1e-9);
  // Columns sorted and distinct in every row (column-major storage: rows are columns here).
  for (Eigen::Index c = 0; c < n; ++c)
    for (int q = A.outerIndexPtr()[c] + 1; q < A.outerIndexPtr()[c + 1]; ++q)
      ASSERT_LT(A.innerIndexPtr()[q - 1], A.innerIndexPtr()[q]) << "column " << c;
  // A row with more than 32 distinct columns exists (the pair-sort path ran).
  Eigen::Index widest = 0;
  for (Eigen::Index c = 0; c < n; ++c)
    widest = std::max<Eigen::Index>(widest, A.outerIndexPtr()[c + 1] - A.outerIndexPtr()[c]);
  EXPECT_GT(widest, 32);
}
