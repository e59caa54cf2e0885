// Internal: builds a symmetric sparse matrix row by row, straight in compressed form.
//
// At a million faces the matrices of the N-step, the v-step and the vertex update have 4–20
// million entries; building them from triplets or sparse products cost seconds, most of it
// moving memory. Here each row is written once into its own slot (in parallel), sorted and
// merged there, and the slots are compacted.
#pragma once
#include <Eigen/SparseCore>
#include <algorithm>
#include <utility>
#include <vector>

#include "parallel.h"

namespace msmesh::detail {

/// n by n symmetric matrix from rows: `capacity(i)` bounds the entries of row i and
/// `row(i, cols, vals)` writes them (any order, repeated columns allowed: they are summed)
/// and returns their number. Because the matrix is symmetric, its rows are its columns and
/// the result is returned in Eigen's default column-major storage.
template <class Capacity, class Row>
Eigen::SparseMatrix<double> symmetric_from_rows(Eigen::Index n, Capacity&& capacity, Row&& row) {
  std::vector<Eigen::Index> cap(static_cast<size_t>(n) + 1, 0);
  for (Eigen::Index i = 0; i < n; ++i) cap[static_cast<size_t>(i) + 1] = cap[static_cast<size_t>(i)] + capacity(i);
  std::vector<int> col(static_cast<size_t>(cap.back()));
  std::vector<double> val(static_cast<size_t>(cap.back()));
  std::vector<int> count(static_cast<size_t>(n));
  parallel_for(n, [&](Eigen::Index i) {
    const size_t b = static_cast<size_t>(cap[static_cast<size_t>(i)]);
    const size_t m = static_cast<size_t>(row(i, col.data() + b, val.data() + b));
    if (m <= 16) {
      for (size_t a = b + 1; a < b + m; ++a)  // insertion sort for short rows
        for (size_t k = a; k > b && col[k] < col[k - 1]; --k) {
          std::swap(col[k], col[k - 1]);
          std::swap(val[k], val[k - 1]);
        }
    } else {  // (column, value) pairs: the sort is deterministic, so is the sum of repeats
      thread_local std::vector<std::pair<int, double>> pairs;
      pairs.resize(m);
      for (size_t a = 0; a < m; ++a) pairs[a] = {col[b + a], val[b + a]};
      std::sort(pairs.begin(), pairs.end());
      for (size_t a = 0; a < m; ++a) {
        col[b + a] = pairs[a].first;
        val[b + a] = pairs[a].second;
      }
    }
    size_t last = b;
    for (size_t a = b + 1; a < b + m; ++a) {
      if (col[a] == col[last]) {
        val[last] += val[a];
      } else {
        ++last;
        col[last] = col[a];
        val[last] = val[a];
      }
    }
    count[static_cast<size_t>(i)] = m == 0 ? 0 : static_cast<int>(last - b + 1);
  });
  Eigen::SparseMatrix<double> A(n, n);
  Eigen::Index nnz = 0;
  for (Eigen::Index i = 0; i < n; ++i) nnz += count[static_cast<size_t>(i)];
  A.resizeNonZeros(nnz);
  int* outer = A.outerIndexPtr();
  outer[0] = 0;
  for (Eigen::Index i = 0; i < n; ++i) outer[i + 1] = outer[i] + count[static_cast<size_t>(i)];
  parallel_for(n, [&](Eigen::Index i) {
    const size_t b = static_cast<size_t>(cap[static_cast<size_t>(i)]);
    for (int k = 0; k < count[static_cast<size_t>(i)]; ++k) {
      A.innerIndexPtr()[outer[i] + k] = col[b + static_cast<size_t>(k)];
      A.valuePtr()[outer[i] + k] = val[b + static_cast<size_t>(k)];
    }
  });
  return A;
}

}  // namespace msmesh::detail
