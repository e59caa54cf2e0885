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

/// Sums the repeated columns of one row (m pairs at col/val) in place, sorted by column;
/// returns the number of distinct columns. `n`: the matrix size (for the column map).
inline size_t merge_row(int* col, double* val, size_t m, Eigen::Index n) {
  if (m <= 16) {  // short rows: sort, then sum the repeats
    insertion_sort(col, val, m);
    size_t last = 0;
    for (size_t a = 1; a < m; ++a) {
      if (col[a] == col[last]) {
        val[last] += val[a];
      } else {
        ++last;
        col[last] = col[a];
        val[last] = val[a];
      }
    }
    return m == 0 ? 0 : last + 1;
  }
  // Long rows (the vertex update: ~70 entries, ~20 distinct columns): sum the repeats through a
  // column → slot map in the order the row wrote them (deterministic), then sort the few
  // distinct columns. A sort of all the pairs took 80 % of the assembly.
  thread_local std::vector<int> slot;
  if (slot.size() < static_cast<size_t>(n)) slot.assign(static_cast<size_t>(n), -1);
  size_t u = 0;
  for (size_t a = 0; a < m; ++a) {
    const int c = col[a];
    int& sl = slot[static_cast<size_t>(c)];
    if (sl < 0) {
      sl = static_cast<int>(u);
      col[u] = c;
      val[u] = val[a];
      ++u;
    } else {
      val[static_cast<size_t>(sl)] += val[a];
    }
  }
  for (size_t a = 0; a < u; ++a) slot[static_cast<size_t>(col[a])] = -1;
  if (u <= 32) {
    insertion_sort(col, val, u);
  } else {  // a high-valence vertex: O(u log u) (the columns are distinct, so any sort gives the same)
    thread_local std::vector<std::pair<int, double>> pairs;
    pairs.resize(u);
    for (size_t a = 0; a < u; ++a) pairs[a] = {col[a], val[a]};
    std::sort(pairs.begin(), pairs.end());
    for (size_t a = 0; a < u; ++a) {
      col[a] = pairs[a].first;
      val[a] = pairs[a].second;
    }
  }
  return u;
}

/// n by n symmetric matrix from rows: `capacity(i)` bounds the entries of row i and
/// `row(i, cols, vals)` writes them (any order, repeated columns allowed: they are summed)
/// and returns their number. Because the matrix is symmetric, its rows are its columns and
/// the result is returned in Eigen's default column-major storage.
///
/// Rows are written a block at a time into a scratch of their capacities, merged there and
/// kept compacted, so the scratch stays small (the vertex update's rows have ~70 entries
/// before merging and ~20 after: a scratch for all rows was the peak memory of a denoise). A
/// block holds kBlockEntries of capacity (6 MB of scratch) or kBlockRows rows: a scratch of
/// 65536 vertex-update rows (53 MB) no longer fitted the memory the normal filter had freed and
/// raised the 82K-face sphere's peak by 18 MB.
template <class Capacity, class Row>
Eigen::SparseMatrix<double> symmetric_from_rows(Eigen::Index n, Capacity&& capacity, Row&& row) {
  constexpr Eigen::Index kBlockRows = Eigen::Index(1) << 16, kBlockEntries = Eigen::Index(1) << 19;
  struct Block {
    std::vector<int> col, count;
    std::vector<double> val;
  };
  std::vector<Block> blocks;
  std::vector<Eigen::Index> cap;
  std::vector<int> col;
  std::vector<double> val;
  std::vector<size_t> start;
  Eigen::Index nnz = 0;
  for (Eigen::Index r0 = 0, rows = 0; r0 < n; r0 += rows) {
    cap.assign(1, 0);
    for (rows = 0; r0 + rows < n && rows < kBlockRows && cap.back() < kBlockEntries; ++rows)
      cap.push_back(cap.back() + capacity(r0 + rows));
    col.resize(static_cast<size_t>(cap.back()));
    val.resize(static_cast<size_t>(cap.back()));
    Block& bl = blocks.emplace_back();
    bl.count.resize(static_cast<size_t>(rows));
    const Eigen::Index row_weight = std::max<Eigen::Index>(1, cap.back() / std::max<Eigen::Index>(1, 4 * rows));
    parallel_for(
        rows,
        [&](Eigen::Index i) {
          const size_t b = static_cast<size_t>(cap[static_cast<size_t>(i)]);
          const size_t m = static_cast<size_t>(row(r0 + i, col.data() + b, val.data() + b));
          bl.count[static_cast<size_t>(i)] = static_cast<int>(merge_row(col.data() + b, val.data() + b, m, n));
        },
        row_weight);
    // Compacted in parallel, each row to the sum of the counts before it.
    start.assign(static_cast<size_t>(rows) + 1, 0);
    for (Eigen::Index i = 0; i < rows; ++i)
      start[static_cast<size_t>(i) + 1] = start[static_cast<size_t>(i)] + bl.count[static_cast<size_t>(i)];
    const size_t total = start.back();
    bl.col.resize(total);
    bl.val.resize(total);
    parallel_for_blocks(rows, [&](Eigen::Index i0, Eigen::Index i1) {
      for (Eigen::Index i = i0; i < i1; ++i) {
        const size_t b = static_cast<size_t>(cap[static_cast<size_t>(i)]);
        const size_t c = static_cast<size_t>(bl.count[static_cast<size_t>(i)]);
        std::copy_n(col.data() + b, c, bl.col.data() + start[static_cast<size_t>(i)]);
        std::copy_n(val.data() + b, c, bl.val.data() + start[static_cast<size_t>(i)]);
      }
    });
    nnz += static_cast<Eigen::Index>(total);
  }
  std::vector<int>().swap(col);
  std::vector<double>().swap(val);
  Eigen::SparseMatrix<double> A(n, n);
  A.resizeNonZeros(nnz);
  int* outer = A.outerIndexPtr();
  outer[0] = 0;
  Eigen::Index i = 0;
  std::vector<Eigen::Index> at(blocks.size());
  for (size_t b = 0; b < blocks.size(); ++b) {
    at[b] = outer[i];
    for (const int c : blocks[b].count) {
      outer[i + 1] = outer[i] + c;
      ++i;
    }
  }
  // The blocks into place side by side (in parallel: the first touch of A's pages is most of
  // this copy's cost).
  const Eigen::Index nb = static_cast<Eigen::Index>(blocks.size());
#pragma omp parallel for schedule(dynamic) if (nnz >= kParallelMin)
  for (Eigen::Index b = 0; b < nb; ++b) {
    Block& bl = blocks[static_cast<size_t>(b)];
    std::copy(bl.col.begin(), bl.col.end(), A.innerIndexPtr() + at[static_cast<size_t>(b)]);
    std::copy(bl.val.begin(), bl.val.end(), A.valuePtr() + at[static_cast<size_t>(b)]);
    std::vector<int>().swap(bl.col);
    std::vector<double>().swap(bl.val);
  }
  return A;
}

}  // namespace msmesh::detail
