// Internal: builds a symmetric sparse matrix row by row, straight in compressed form.
//
// At a million faces the matrices of the N-step, the v-step and the vertex update have 4–20
// million entries; building them from triplets or sparse products cost seconds, most of it
// moving memory. Here each row is written once into its own slot (in parallel), its repeated
// columns merged and sorted there, and the slots are compacted.
#pragma once
#include <Eigen/SparseCore>
#include <algorithm>
#include <utility>
#include <vector>

#include "parallel.h"

namespace msmesh::detail {

/// Sorts m (column, value) pairs by column (stable).
inline void insertion_sort(int* col, double* val, size_t m) {
  for (size_t a = 1; a < m; ++a)
    for (size_t k = a; k > 0 && col[k] < col[k - 1]; --k) {
      std::swap(col[k], col[k - 1]);
      std::swap(val[k], val[k - 1]);
    }
}

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
  const Eigen::Index row_weight = std::max<Eigen::Index>(1, cap.back() / std::max<Eigen::Index>(1, 4 * n));
  parallel_for(
      n,
      [&](Eigen::Index i) {
        const size_t b = static_cast<size_t>(cap[static_cast<size_t>(i)]);
        size_t m = static_cast<size_t>(row(i, col.data() + b, val.data() + b));
        if (m <= 16) {  // short rows: sort, then sum the repeats
          insertion_sort(col.data() + b, val.data() + b, m);
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
          m = m == 0 ? 0 : last - b + 1;
        } else {
          // Long rows (the vertex update: ~70 entries, ~20 distinct columns): sum the repeats
          // through a column → slot map in the order the row wrote them (deterministic), then
          // sort the few distinct columns. A sort of all the pairs took 80 % of the assembly.
          thread_local std::vector<int> slot;
          if (slot.size() < static_cast<size_t>(n)) slot.assign(static_cast<size_t>(n), -1);
          size_t u = 0;
          for (size_t a = 0; a < m; ++a) {
            const int c = col[b + a];
            int& s = slot[static_cast<size_t>(c)];
            if (s < 0) {
              s = static_cast<int>(u);
              col[b + u] = c;
              val[b + u] = val[b + a];
              ++u;
            } else {
              val[b + static_cast<size_t>(s)] += val[b + a];
            }
          }
          for (size_t a = 0; a < u; ++a) slot[static_cast<size_t>(col[b + a])] = -1;
          if (u <= 32) {
            insertion_sort(col.data() + b, val.data() + b, u);
          } else {  // a high-valence vertex: O(u log u) (the columns are distinct, so any sort gives the same)
            thread_local std::vector<std::pair<int, double>> pairs;
            pairs.resize(u);
            for (size_t a = 0; a < u; ++a) pairs[a] = {col[b + a], val[b + a]};
            std::sort(pairs.begin(), pairs.end());
            for (size_t a = 0; a < u; ++a) {
              col[b + a] = pairs[a].first;
              val[b + a] = pairs[a].second;
            }
          }
          m = u;
        }
        count[static_cast<size_t>(i)] = static_cast<int>(m);
      },
      row_weight);
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
