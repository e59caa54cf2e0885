#include "pcg.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "cuthill_mckee.h"
#include "msmesh/errors.h"
#include "parallel.h"
#include "sparse_build.h"
#include "wide_rows.h"

namespace msmesh::detail {

namespace {

// Sums of C columns, K of them at once, in a fixed order (parallel.h).
template <int C, int K, class Body>
std::array<std::array<double, C>, K> column_sums(Eigen::Index n, Body&& body, Eigen::Index row_weight = 1) {
  const auto flat = deterministic_sums<C * K>(
      n,
      [&](Eigen::Index i0, Eigen::Index i1, std::array<double, C * K>& s) {
        std::array<std::array<double, C>, K> t{};
        body(i0, i1, t);
        for (int k = 0; k < K; ++k)
          for (int c = 0; c < C; ++c) s[C * k + c] += t[k][c];
      },
      row_weight);
  std::array<std::array<double, C>, K> out{};
  for (int k = 0; k < K; ++k)
    for (int c = 0; c < C; ++c) out[k][c] = flat[C * k + c];
  return out;
}

}  // namespace

RowMatrixX3 to_rows(const Eigen::MatrixXd& M) { return RowMatrixX3(M); }

namespace {

// The reverse Cuthill–McKee order of the compressed rows of a symmetric matrix.
std::vector<int> matrix_order(const Eigen::Map<const RowSparse>& A) {
  std::vector<int> degree(static_cast<size_t>(A.rows()));
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    degree[static_cast<size_t>(i)] = A.outerIndexPtr()[i + 1] - A.outerIndexPtr()[i];
  return reverse_cuthill_mckee(degree, [&](int u, auto&& visit) {
    for (Eigen::Map<const RowSparse>::InnerIterator it(A, u); it; ++it) visit(static_cast<int>(it.col()));
  });
}

}  // namespace

template <class Stored>
BasicBlockPcg<Stored>::BasicBlockPcg(const Eigen::SparseMatrix<double>& A, bool reorder) {
  init(A, reorder);
}

template <class Stored>
BasicBlockPcg<Stored>::BasicBlockPcg(const Eigen::SparseMatrix<double>& A, std::vector<int> order) {
  if (!order.empty() && order.size() != static_cast<size_t>(A.rows()))
    throw SolverError("conjugate gradients: an order of " + std::to_string(order.size()) + " rows for a matrix of " +
                      std::to_string(A.rows()));
  init(A, /*reorder=*/false, std::move(order));
}

template <class Stored>
BasicBlockPcg<Stored>::BasicBlockPcg(Eigen::Index n, const FixedWidthRows& rows, std::vector<int> order) {
  if (!order.empty() && order.size() != static_cast<size_t>(n))
    throw SolverError("conjugate gradients: an order of " + std::to_string(order.size()) + " rows for a matrix of " +
                      std::to_string(n));
  // The rows in their own numbering, each column once: repeats summed in the order of their
  // columns (as the assembled matrix's merge), then the diagonal and the rest apart.
  constexpr int W = kEllWidth;
  std::vector<int> cols(static_cast<size_t>(W * n), -1), count(static_cast<size_t>(n));
  std::vector<double> vals(static_cast<size_t>(W * n)), diag(static_cast<size_t>(n));
  std::vector<char> too_wide(static_cast<size_t>((n + kBlock - 1) / kBlock), 0);
  parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
    for (Eigen::Index i = i0; i < i1; ++i) {
      // Written into room for more than W entries, so that a row of too many is refused
      // without writing over the next row's.
      int c[kFixedWidthRoom];
      double v[kFixedWidthRoom];
      const int m = rows(i, &diag[static_cast<size_t>(i)], c, v);
      if (m > W) {
        too_wide[static_cast<size_t>(i0 / kBlock)] = 1;
        return;
      }
      const size_t u = merge_row(c, v, static_cast<size_t>(m), n);  // (a short row: sorted, then summed)
      std::copy(c, c + u, cols.data() + W * i);
      std::copy(v, v + u, vals.data() + W * i);
      count[static_cast<size_t>(i)] = static_cast<int>(u);
    }
  });
  if (std::find(too_wide.begin(), too_wide.end(), 1) != too_wide.end())
    throw SolverError("conjugate gradients: a row of a fixed-width matrix has more than " + std::to_string(W) +
                      " entries beside the diagonal");
  if (order.empty()) {
    std::vector<int> degree(count.size());
    for (size_t i = 0; i < count.size(); ++i) degree[i] = 1 + count[i];
    order = reverse_cuthill_mckee(degree, [&](int u, auto&& visit) {
      for (int k = 0; k < count[static_cast<size_t>(u)]; ++k) visit(cols[static_cast<size_t>(W * u + k)]);
    });
  }
  perm_ = std::move(order);
  std::vector<int> inverse(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    inverse[static_cast<size_t>(perm_[static_cast<size_t>(i)])] = static_cast<int>(i);
  // Row i of P A Pᵀ: its entries sorted by their new columns, padded with zeros at column i;
  // every value rounded to Stored once, as the copy of an assembled matrix does.
  ell_cols_.resize(static_cast<size_t>(W * n));
  ell_vals_.resize(static_cast<size_t>(W * n));
  ell_diag_.resize(static_cast<size_t>(n));
  inv_diag_.resize(n);
  std::vector<char> bad(too_wide.size(), 0);
  parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
    for (Eigen::Index i = i0; i < i1; ++i) {
      const size_t o = static_cast<size_t>(perm_[static_cast<size_t>(i)]);
      int c[W];
      double v[W];
      const int m = count[o];
      for (int k = 0; k < m; ++k) {
        c[k] = inverse[static_cast<size_t>(cols[W * o + k])];
        v[k] = vals[W * o + k];
      }
      insertion_sort(c, v, static_cast<size_t>(m));
      for (int k = 0; k < W; ++k) {
        ell_cols_[static_cast<size_t>(W * i + k)] = k < m ? c[k] : static_cast<int>(i);
        ell_vals_[static_cast<size_t>(W * i + k)] = k < m ? static_cast<Stored>(v[k]) : Stored(0);
      }
      const Stored d = static_cast<Stored>(diag[o]);
      ell_diag_[static_cast<size_t>(i)] = d;
      inv_diag_(i) = static_cast<Stored>(1.0 / double(d));
      if (!(double(d) > 0) || !std::isfinite(double(d))) bad[static_cast<size_t>(i0 / kBlock)] = 1;
    }
  });
  A_ = Eigen::SparseMatrix<Stored>();  // (0 by 0: with n = 0 the dispatch takes the compressed layout, as before)
  if (std::find(bad.begin(), bad.end(), 1) != bad.end())
    for (Eigen::Index i = 0; i < n && bad_row_ < 0; ++i)
      note_bad_diagonal(i, double(ell_diag_[static_cast<size_t>(i)]));
}

template <class Stored>
BasicBlockPcg<Stored>::BasicBlockPcg(Eigen::SparseMatrix<double>&& A, bool reorder) {
  bool sorted = std::is_same_v<Stored, double> && !reorder && A.isCompressed();
  if (sorted) {  // every row's columns increasing (in parallel blocks: ten million entries at 1.3M faces)
    const Eigen::Index n = A.outerSize();
    std::vector<char> unsorted(static_cast<size_t>((n + kBlock - 1) / kBlock), 0);
    parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
      for (Eigen::Index i = i0; i < i1; ++i)
        for (int j = A.outerIndexPtr()[i] + 1; j < A.outerIndexPtr()[i + 1]; ++j)
          if (A.innerIndexPtr()[j] <= A.innerIndexPtr()[j - 1]) unsorted[static_cast<size_t>(i0 / kBlock)] = 1;
    });
    sorted = std::find(unsorted.begin(), unsorted.end(), 1) == unsorted.end();
  }
  if (!sorted) {
    init(A, reorder);
    return;
  }
  // The rows the copy below would make, in the same order: the same products, bit for bit.
  if constexpr (std::is_same_v<Stored, double>) A_ = std::move(A);
  find_diagonal();
}

template <class Stored>
void BasicBlockPcg<Stored>::init(const Eigen::SparseMatrix<double>& A, bool reorder, std::vector<int> order) {
  // A is symmetric, so its compressed columns are its rows: read them in place rather than
  // converting (a copy of A, the largest array of the vertex update).
  Eigen::SparseMatrix<double> compressed;
  const Eigen::SparseMatrix<double>* src = &A;
  if (!A.isCompressed()) {
    compressed = A;
    compressed.makeCompressed();
    src = &compressed;
  }
  const Eigen::Map<const RowSparse> A0(src->rows(), src->cols(), src->nonZeros(), src->outerIndexPtr(),
                                       src->innerIndexPtr(), src->valuePtr());
  const Eigen::Index n = A0.rows();
  perm_ = reorder ? matrix_order(A0) : std::move(order);
  auto old_row = [&](Eigen::Index i) { return perm_.empty() ? static_cast<int>(i) : perm_[static_cast<size_t>(i)]; };
  std::vector<int> inverse(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) inverse[static_cast<size_t>(old_row(i))] = static_cast<int>(i);
  // A_ = P A Pᵀ in compressed row-major form, columns sorted within each row: the row
  // starts first (a prefix sum of the row lengths), then the rows independently, in parallel.
  A_.resize(n, n);
  A_.resizeNonZeros(A0.nonZeros());
  int* outer = A_.outerIndexPtr();
  int* inner = A_.innerIndexPtr();
  Stored* val = A_.valuePtr();
  const int* outer0 = A0.outerIndexPtr();
  outer[0] = 0;
  for (Eigen::Index i = 0; i < n; ++i) outer[i + 1] = outer[i] + outer0[old_row(i) + 1] - outer0[old_row(i)];
  parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
    std::vector<std::pair<int, double>> row;
    for (Eigen::Index i = i0; i < i1; ++i) {
      row.clear();
      for (Eigen::Map<const RowSparse>::InnerIterator it(A0, old_row(i)); it; ++it)
        row.emplace_back(inverse[static_cast<size_t>(it.col())], it.value());
      std::sort(row.begin(), row.end());
      int k = outer[i];
      for (const auto& [c, v] : row) {
        inner[k] = c;
        val[k++] = static_cast<Stored>(v);
      }
    }
  });
  find_diagonal();
  to_fixed_width();
}

template <class Stored>
void BasicBlockPcg<Stored>::to_fixed_width() {
  const Eigen::Index n = A_.rows();
  const int* outer = A_.outerIndexPtr();
  const int* inner = A_.innerIndexPtr();
  const Stored* val = A_.valuePtr();
  if (n == 0) return;  // nothing to gain; the dispatch tells the layouts apart by ell_cols_
  for (Eigen::Index i = 0; i < n; ++i) {
    int off = 0;
    for (int j = outer[i]; j < outer[i + 1]; ++j) off += inner[j] != i;
    if (off > kEllWidth) return;
  }
  ell_cols_.resize(static_cast<size_t>(kEllWidth * n));
  ell_vals_.resize(static_cast<size_t>(kEllWidth * n));
  ell_diag_.resize(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    int k = 0;
    double d = 0;
    for (int j = outer[i]; j < outer[i + 1]; ++j) {
      if (inner[j] == i) {
        d += double(val[j]);
        continue;
      }
      ell_cols_[static_cast<size_t>(kEllWidth * i + k)] = inner[j];
      ell_vals_[static_cast<size_t>(kEllWidth * i + k++)] = val[j];
    }
    for (; k < kEllWidth; ++k) {
      ell_cols_[static_cast<size_t>(kEllWidth * i + k)] = static_cast<int>(i);
      ell_vals_[static_cast<size_t>(kEllWidth * i + k)] = 0;
    }
    ell_diag_[static_cast<size_t>(i)] = static_cast<Stored>(d);
  }
  A_ = Eigen::SparseMatrix<Stored>();
  diag_pos_ = {};
}

template <class Stored>
void BasicBlockPcg<Stored>::find_diagonal() {
  const Eigen::Index n = A_.rows();
  const int* outer = A_.outerIndexPtr();
  const int* inner = A_.innerIndexPtr();
  const Stored* val = A_.valuePtr();
  diag_pos_.assign(static_cast<size_t>(n), -1);
  inv_diag_.resize(n);
  auto diagonal = [&](Eigen::Index i) {
    double d = 0;
    for (int j = outer[i]; j < outer[i + 1]; ++j)
      if (inner[j] == i) {
        d += val[j];
        diag_pos_[static_cast<size_t>(i)] = j;
      }
    return d;
  };
  // In parallel blocks (two million rows of the v-step at a million faces); the first row
  // with a bad entry, if any, is looked for afterwards in row order.
  std::vector<char> bad(static_cast<size_t>((n + kBlock - 1) / kBlock), 0);
  parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
    for (Eigen::Index i = i0; i < i1; ++i) {
      const double d = diagonal(i);
      if (!(d > 0) || !std::isfinite(d)) bad[static_cast<size_t>(i0 / kBlock)] = 1;
      inv_diag_(i) = static_cast<Stored>(1.0 / d);
    }
  });
  if (std::find(bad.begin(), bad.end(), 1) != bad.end())
    for (Eigen::Index i = 0; i < n && bad_row_ < 0; ++i) note_bad_diagonal(i, diagonal(i));
}

// Notes row i (position in the order) as the first with a diagonal entry d that is not
// positive, unless one is noted already.
template <class Stored>
void BasicBlockPcg<Stored>::note_bad_diagonal(Eigen::Index i, double d) {
  if (bad_row_ >= 0 || (d > 0 && std::isfinite(d))) return;
  bad_row_ = perm_.empty() ? i : perm_[static_cast<size_t>(i)];
  bad_value_ = d;
}

template <class Stored>
void BasicBlockPcg<Stored>::set_diagonal(const Eigen::VectorXd& d) {
  // In parallel blocks (the v-step's two million rows at a million faces: serial, this pass
  // took as long as the solve's sweeps); each block notes whether it met a missing or
  // non-positive entry and its largest Gershgorin ratio, and the first bad row is looked for
  // afterwards, in row order, only when there is one.
  const Eigen::Index n = size();
  Stored* val = A_.valuePtr();
  const Eigen::Index nb = (n + kBlock - 1) / kBlock;
  std::vector<double> block_radius(static_cast<size_t>(nb), 0.0);
  std::vector<char> block_bad(static_cast<size_t>(nb), 0);
  auto original = [&](Eigen::Index i) {
    return perm_.empty() ? i : static_cast<Eigen::Index>(perm_[static_cast<size_t>(i)]);
  };
  parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
    double radius = 0;
    char bad = 0;
    for (Eigen::Index i = i0; i < i1; ++i) {
      const double di = d(original(i));
      if (!ell_diag_.empty()) {
        ell_diag_[static_cast<size_t>(i)] = static_cast<Stored>(di);
      } else {
        const int j = diag_pos_[static_cast<size_t>(i)];
        if (j >= 0) val[j] = static_cast<Stored>(di);
        bad |= j < 0;
      }
      bad |= !(di > 0) || !std::isfinite(di);
      const double inv = 1.0 / di;
      inv_diag_(i) = static_cast<Stored>(inv);
      if (chebyshev_) radius = std::max(radius, double(off_sums_[static_cast<size_t>(i)]) / di);
    }
    block_radius[static_cast<size_t>(i0 / kBlock)] = radius;
    block_bad[static_cast<size_t>(i0 / kBlock)] = bad;
  });
  bad_row_ = -1;
  if (std::find(block_bad.begin(), block_bad.end(), 1) != block_bad.end()) {
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Index o = original(i);
      if (ell_diag_.empty() && diag_pos_[static_cast<size_t>(i)] < 0)
        throw SolverError("conjugate gradients: the matrix does not store diagonal entry " + std::to_string(o));
      if (!(d(o) > 0) || !std::isfinite(d(o))) {
        bad_row_ = o;
        bad_value_ = d(o);
        break;
      }
    }
  }
  if (chebyshev_)  // a new spectrum
    set_spectrum(block_radius.empty() ? 0.0 : *std::max_element(block_radius.begin(), block_radius.end()));
}

template <class Stored>
PcgStats BasicBlockPcg<Stored>::solve(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance,
                                      int max_iterations, const std::string& what) const {
  return solve_reordered<3>(B, X, relative_tolerance, max_iterations, what);
}

template <class Stored>
PcgStats BasicBlockPcg<Stored>::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double relative_tolerance,
                                      int max_iterations, const std::string& what) const {
  return solve_reordered<1>(b, x, relative_tolerance, max_iterations, what);
}

template <class Stored>
PcgStats BasicBlockPcg<Stored>::solve_in_order(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance,
                                               int max_iterations, const std::string& what) const {
  check_diagonal();
  return solve_permuted<3>(B.data(), X.data(), relative_tolerance, max_iterations, what);
}

template <class Stored>
void BasicBlockPcg<Stored>::check_diagonal() const {
  if (bad_row_ >= 0) {
    std::ostringstream os;
    os << "conjugate gradients: diagonal entry " << bad_row_ << " = " << bad_value_ << " is not positive";
    throw SolverError(os.str());
  }
}

template <class Stored>
template <int K, class M>
PcgStats BasicBlockPcg<Stored>::solve_reordered(const M& B, M& X, double relative_tolerance, int max_iterations,
                                                const std::string& what) const {
  check_diagonal();
  if (perm_.empty()) return solve_permuted<K>(B.data(), X.data(), relative_tolerance, max_iterations, what);
  const Eigen::Index n = size();
  Bp_.resize(static_cast<size_t>(K * n));
  Xp_.resize(static_cast<size_t>(K * n));
  parallel_for(n, [&](Eigen::Index i) {
    const Eigen::Index o = perm_[static_cast<size_t>(i)];
    for (int c = 0; c < K; ++c) {
      Bp_[static_cast<size_t>(K * i + c)] = B.data()[K * o + c];
      Xp_[static_cast<size_t>(K * i + c)] = X.data()[K * o + c];
    }
  });
  const PcgStats st = solve_permuted<K>(Bp_.data(), Xp_.data(), relative_tolerance, max_iterations, what);
  parallel_for(n, [&](Eigen::Index i) {
    const Eigen::Index o = perm_[static_cast<size_t>(i)];
    for (int c = 0; c < K; ++c) X.data()[K * o + c] = Xp_[static_cast<size_t>(K * i + c)];
  });
  return st;
}

template <class Stored>
template <int K>
PcgStats BasicBlockPcg<Stored>::solve_permuted(const double* B, double* X, double relative_tolerance,
                                               int max_iterations, const std::string& what) const {
  // Three columns on rows padded to four where the wide loops (wide_rows.h) exist for the
  // layout: any fixed-width matrix (the N-step's, the polish's) and a compressed double one
  // (the vertex update's).
  if constexpr (K == 3) {
    if (wide_rows()) {
      if (!ell_cols_.empty()) return solve_layout<3, true, 4>(B, X, relative_tolerance, max_iterations, what);
      if constexpr (std::is_same_v<Stored, double>)
        return solve_layout<3, false, 4>(B, X, relative_tolerance, max_iterations, what);
    }
  }
  return ell_cols_.empty() ? solve_layout<K, false, K>(B, X, relative_tolerance, max_iterations, what)
                           : solve_layout<K, true, K>(B, X, relative_tolerance, max_iterations, what);
}

// CG on the reordered system, B and X n by K row-major (element (i, c) at K·i + c), the work
// vectors n by S (K, or 4 for the wide rows: element (i, c) at S·i + c, the fourth 0); Ell: the
// matrix in the fixed-width layout.
// a = (A v)_i: in the fixed-width layout the diagonal, then kEllWidth entries (a row's unused
// slots hold 0 at its own column); otherwise the compressed row.
template <class Stored>
template <int K, int S, bool Ell, class T>
inline void BasicBlockPcg<Stored>::row_product(Eigen::Index i, const T* __restrict v, double* a) const {
  if constexpr (Ell) {
    for (int c = 0; c < K; ++c) a[c] = double(ell_diag_[static_cast<size_t>(i)]) * double(v[S * i + c]);
    for (int k = 0; k < kEllWidth; ++k) {
      const double w = ell_vals_[static_cast<size_t>(kEllWidth * i + k)];
      const T* vj = v + S * static_cast<Eigen::Index>(ell_cols_[static_cast<size_t>(kEllWidth * i + k)]);
      for (int c = 0; c < K; ++c) a[c] += w * double(vj[c]);
    }
  } else {
    const int* outer = A_.outerIndexPtr();
    const int* inner = A_.innerIndexPtr();
    const Stored* val = A_.valuePtr();
    for (int c = 0; c < K; ++c) a[c] = 0;
    const int j1 = outer[i + 1];
    for (int j = outer[i]; j < j1; ++j) {
      const double w = val[j];
      const T* vj = v + S * static_cast<Eigen::Index>(inner[j]);
      for (int c = 0; c < K; ++c) a[c] += w * double(vj[c]);
    }
  }
}

template <class Stored>
template <int K, bool Ell, int S>
PcgStats BasicBlockPcg<Stored>::solve_layout(const double* B, double* X, double relative_tolerance, int max_iterations,
                                             const std::string& what) const {
  if (chebyshev_ && lambda_min_ > 0) return solve_chebyshev<K, Ell, S>(B, X, relative_tolerance, max_iterations, what);
  using Sums = std::array<double, K>;
  const Eigen::Index n = size();
  const Stored* inv_d = inv_diag_.data();
  // Work space kept between calls (no allocation, no page faults in the iterations).
  R_.resize(static_cast<size_t>(S * n));
  P_.resize(static_cast<size_t>(S * n));
  Q_.resize(static_cast<size_t>(S * n));
  Stored* Rp = R_.data();
  Stored* Pw = P_.data();
  Stored* Qp = Q_.data();

  // r = b − A x, p = D⁻¹ r; sums: ‖b‖², r·D⁻¹r, ‖r‖² (of the stored r and p).
  const auto s0 = column_sums<K, 3>(
      n,
      [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 3>& s) {
        for (Eigen::Index i = i0; i < i1; ++i) {
          double ax[K];
          row_product<K, K, Ell>(i, X, ax);
          for (int c = K; c < S; ++c) Rp[S * i + c] = Pw[S * i + c] = 0;  // the padding
          for (int c = 0; c < K; ++c) {
            const double b = B[K * i + c];
            const Stored r = static_cast<Stored>(b - ax[c]), z = static_cast<Stored>(double(r) * double(inv_d[i]));
            Rp[S * i + c] = r;
            Pw[S * i + c] = z;
            s[0][c] += b * b;
            s[1][c] += double(r) * double(z);
            s[2][c] += double(r) * double(r);
          }
        }
      },
      product_weight<Ell>());
  Sums tol{}, rz = s0[1];
  std::array<bool, K> done{};
  PcgStats stats;
  for (int c = 0; c < K; ++c) {
    tol[c] = relative_tolerance * std::sqrt(s0[0][c]);
    if (s0[0][c] == 0) {  // b = 0: the solution is 0
      for (Eigen::Index i = 0; i < n; ++i) X[K * i + c] = 0;
      done[c] = true;
      continue;
    }
    done[c] = std::sqrt(s0[2][c]) <= tol[c];
    if (!done[c]) stats.relative_residual = std::max(stats.relative_residual, std::sqrt(s0[2][c] / s0[0][c]));
  }
  auto all_done = [&] { return std::all_of(done.begin(), done.end(), [](bool d) { return d; }); };
  for (int c = 0; c < K; ++c)
    if (done[c])
      for (Eigen::Index i = 0; i < n; ++i) Pw[S * i + c] = 0;

  // The Lanczos coefficients of one column (CG's α and β), while the spectrum is not known.
  const bool learn = chebyshev_ && !(lambda_min_ > 0);
  const int lc = static_cast<int>(std::find(done.begin(), done.end(), false) - done.begin());
  std::vector<double> lanczos_alpha, lanczos_beta;
  int it = 0;
  while (!all_done()) {
    if (++it > max_iterations) {
      std::ostringstream os;
      os << what << ": conjugate gradients did not reach relative residual " << relative_tolerance << " in "
         << max_iterations << " iterations (at " << stats.relative_residual << ")";
      throw SolverError(os.str());
    }
    // q = A p, p·q.
    const auto s1 = column_sums<K, 1>(
        n,
        [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 1>& s) {
          const Stored* __restrict p = Pw;
          Stored* __restrict q = Qp;
          Sums pq{};
          if constexpr (S == 4 && Ell) {
            product_wide(i0, i1, ell_diag_.data(), ell_vals_.data(), ell_cols_.data(), p, q, pq.data());
          } else if constexpr (S == 4 && std::is_same_v<Stored, double>) {
            product_wide(i0, i1, A_.outerIndexPtr(), A_.innerIndexPtr(), A_.valuePtr(), p, q, pq.data());
          } else {
            for (Eigen::Index i = i0; i < i1; ++i) {
              double a[K];
              row_product<K, S, Ell>(i, p, a);
              for (int c = 0; c < K; ++c) {
                const Stored qc = static_cast<Stored>(a[c]);
                q[S * i + c] = qc;
                pq[c] += double(p[S * i + c]) * double(qc);
              }
            }
          }
          s[0] = pq;
        },
        product_weight<Ell>());
    Sums alpha{};
    for (int c = 0; c < K; ++c) alpha[c] = done[c] ? 0.0 : rz[c] / s1[0][c];
    // r −= α q; sums: r·D⁻¹r, ‖r‖². (x += α p waits for the pass that overwrites p, which
    // reads p anyway: one pass over p fewer per sweep, the same arithmetic.)
    const auto s2 = column_sums<K, 2>(
        n,
        [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 2>& s) {
          Stored* __restrict r = Rp;
          const Stored* __restrict q = Qp;
          const Stored* __restrict id = inv_d;
          Sums rzs{}, rrs{};
          if constexpr (S == 4) {
            residual_update_wide(i0, i1, r, q, id, alpha.data(), rzs.data(), rrs.data());
            s[0] = rzs;
            s[1] = rrs;
            return;
          }
          for (Eigen::Index i = i0; i < i1; ++i) {
            const Eigen::Index b = S * i;
            const double di = id[i];
            for (int c = 0; c < K; ++c) {
              const Stored stored = static_cast<Stored>(double(r[b + c]) - alpha[c] * double(q[b + c]));
              const double rc = stored;
              r[b + c] = stored;
              rzs[c] += rc * rc * di;
              rrs[c] += rc * rc;
            }
          }
          s[0] = rzs;
          s[1] = rrs;
        },
        K);
    Sums beta{};
    stats.relative_residual = 0;
    for (int c = 0; c < K; ++c) {
      if (done[c]) continue;
      if (!std::isfinite(s2[1][c]) || !std::isfinite(alpha[c]))
        throw SolverError(what + ": conjugate gradients broke down (non-finite values)");
      const double res = std::sqrt(s2[1][c]);
      stats.relative_residual = std::max(stats.relative_residual, res / std::sqrt(s0[0][c]));
      if (res <= tol[c]) {
        done[c] = true;
      } else {
        beta[c] = s2[0][c] / rz[c];
        rz[c] = s2[0][c];
      }
      if (learn && c == lc) {
        lanczos_alpha.push_back(alpha[c]);
        if (!done[c]) lanczos_beta.push_back(beta[c]);
      }
    }
    if (all_done()) {
      parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
        double* __restrict x = X;
        const Stored* __restrict p = Pw;
        for (Eigen::Index i = i0; i < i1; ++i)
          for (int c = 0; c < K; ++c) x[K * i + c] += alpha[c] * double(p[S * i + c]);
      });
      break;
    }
    // x += α p, then p = D⁻¹ r + β p (0 for the columns that are done).
    Sums keep{};
    for (int c = 0; c < K; ++c) keep[c] = done[c] ? 0.0 : 1.0;
    parallel_for_blocks(
        n,
        [&](Eigen::Index i0, Eigen::Index i1) {
          double* __restrict x = X;
          Stored* __restrict p = Pw;
          const Stored* __restrict r = Rp;
          if constexpr (S == 4) {
            direction_update_wide(i0, i1, x, p, r, inv_d, alpha.data(), keep.data(), beta.data());
            return;
          }
          for (Eigen::Index i = i0; i < i1; ++i) {
            const double di = inv_d[i];
            for (int c = 0; c < K; ++c) {
              const double pc = p[S * i + c];
              x[K * i + c] += alpha[c] * pc;
              p[S * i + c] = static_cast<Stored>(keep[c] * (double(r[S * i + c]) * di + beta[c] * pc));
            }
          }
        },
        K);
  }
  stats.iterations = it;
  if (learn) learn_spectrum(lanczos_alpha, lanczos_beta);
  return stats;
}

namespace {

// Smallest eigenvalue of the symmetric tridiagonal matrix with diagonal a and off-diagonal b
// (b.size() == a.size() − 1), by bisection on the Sturm sequence count.
double smallest_tridiagonal_eigenvalue(const std::vector<double>& a, const std::vector<double>& b) {
  const size_t m = a.size();
  double lo = a[0], hi = a[0];
  for (size_t j = 0; j < m; ++j) {  // Gershgorin interval
    const double radius = (j > 0 ? std::abs(b[j - 1]) : 0.0) + (j + 1 < m ? std::abs(b[j]) : 0.0);
    lo = std::min(lo, a[j] - radius);
    hi = std::max(hi, a[j] + radius);
  }
  auto below = [&](double x) {  // number of eigenvalues < x
    int count = 0;
    double d = 1;
    for (size_t j = 0; j < m; ++j) {
      d = a[j] - x - (j > 0 ? b[j - 1] * b[j - 1] / d : 0.0);
      if (d == 0) d = -1e-300;
      count += d < 0;
    }
    return count;
  };
  for (int k = 0; k < 100 && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++k) {
    const double mid = 0.5 * (lo + hi);
    if (below(mid) >= 1)
      hi = mid;
    else
      lo = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

template <class Stored>
void BasicBlockPcg<Stored>::use_chebyshev(bool gershgorin_lower) {
  chebyshev_ = true;
  gershgorin_lower_ = gershgorin_lower;
  // The off-diagonal row sums Σ_{j≠i} |a_ij| of the matrix as stored (they stay when
  // set_diagonal changes the diagonal).
  const Eigen::Index n = size();
  off_sums_.resize(static_cast<size_t>(n));  // every entry set below
  // radius = max_i Σ_{j≠i} |a_ij| / a_ii (set_spectrum), per block in parallel.
  std::vector<double> block_radius(static_cast<size_t>((n + kBlock - 1) / kBlock), 0.0);
  parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
    double radius = 0;
    for (Eigen::Index i = i0; i < i1; ++i) {
      double off = 0;
      if (!ell_cols_.empty()) {
        for (int k = 0; k < kEllWidth; ++k) off += std::abs(double(ell_vals_[static_cast<size_t>(kEllWidth * i + k)]));
      } else {
        for (int j = A_.outerIndexPtr()[i]; j < A_.outerIndexPtr()[i + 1]; ++j)
          if (A_.innerIndexPtr()[j] != i) off += std::abs(double(A_.valuePtr()[j]));
      }
      off_sums_[static_cast<size_t>(i)] = static_cast<float>(off);
      radius = std::max(radius, double(off_sums_[static_cast<size_t>(i)]) * double(inv_diag_(i)));
    }
    block_radius[static_cast<size_t>(i0 / kBlock)] = radius;
  });
  set_spectrum(block_radius.empty() ? 0.0 : *std::max_element(block_radius.begin(), block_radius.end()));
}

template <class Stored>
void BasicBlockPcg<Stored>::set_spectrum(double radius) {
  // The eigenvalues of D⁻¹A (similar to the symmetric D^{-1/2} A D^{-1/2}, so real) lie in
  // [1 − radius, 1 + radius], radius = max_i Σ_{j≠i} |a_ij| / a_ii (Gershgorin). The upper end
  // is used as it is (no mode above the interval can grow); the lower one only when it gives
  // κ ≤ kGershgorinKappa (a strongly diagonally dominant matrix: the v-step's, κ ≈ 1 + 1e-5),
  // else it is learnt from a CG solve: tighter (the 82K sphere's N-step: 0.36 against
  // Gershgorin's 0.34), the only usable one where a mesh's small faces make single rows nearly
  // singular (Gershgorin's 2e-5 on the Cone's N-step, whose spectrum starts at 0.11), and with
  // it the `smooth` N-step (Gershgorin κ 1.1–2) stays closer to the factorisation's result
  // (test Solver.ConjugateGradientsMatchCholeskyInTheNormalFilter: 1.5e-5 apart with
  // Gershgorin's interval, under 1e-5 with the learnt one).
  lambda_max_ = 1 + radius;
  const double lower = 1 - radius;
  lambda_min_ = lower > 0 && (gershgorin_lower_ || lambda_max_ <= kGershgorinKappa * lower) ? lower : 0;
}

template <class Stored>
void BasicBlockPcg<Stored>::learn_spectrum(const std::vector<double>& alpha, const std::vector<double>& beta) const {
  // CG's coefficients are those of the Lanczos process on D⁻¹A: T has diagonal
  // 1/α_j + β_{j−1}/α_{j−1} and off-diagonal √β_j / α_j. Its smallest eigenvalue (a Ritz
  // value) is at least λ_min; taken as the lower end of Chebyshev's interval, the modes below
  // it still converge, only more slowly.
  const size_t m = alpha.size();
  if (m < static_cast<size_t>(kLanczosSweeps)) return;
  std::vector<double> a(m), b(m - 1);
  for (size_t j = 0; j < m; ++j) {
    if (!(alpha[j] > 0) || !std::isfinite(alpha[j])) return;
    a[j] = 1 / alpha[j] + (j > 0 ? beta[j - 1] / alpha[j - 1] : 0.0);
    if (j + 1 < m) b[j] = std::sqrt(beta[j]) / alpha[j];
  }
  const double theta = smallest_tridiagonal_eigenvalue(a, b);
  if (theta > 0 && theta < lambda_max_) lambda_min_ = theta;
}

// Chebyshev iteration on D⁻¹A with the spectrum in [λ_min, λ_max] (Saad, Iterative Methods
// for Sparse Linear Systems, algorithm 12.1), written as the three-term recurrence of the
// correction y = x − x₀ (Gutknecht and Röllin, "The Chebyshev iteration revisited", 2002):
// y₁ = D⁻¹r₀/θ, y_{k+1} = y_k + c₁(y_k − y_{k−1}) + c₂ D⁻¹(r₀ − A y_k). Its coefficients are
// known in advance, so a sweep is one pass over the rows that reads r₀, y_k and y_{k−1} and
// writes y_{k+1} over y_{k−1}, with one reduction (‖r_k‖² for the stopping test); x is read
// and written once, at the end. In single precision the correction and r₀ are stored as
// floats: each is small against x and b, so their rounding is relative to the residual the
// solve starts from, not to the solution (about 80 bytes per row and sweep of the N-step
// instead of the 140 of the recurrence on x, r and the direction). Stops on the same test as
// CG; if it has not converged within twice the sweeps its rate promises (a spectrum wider than
// estimated), CG takes over from where it got to.
template <class Stored>
template <int K, bool Ell, int S>
PcgStats BasicBlockPcg<Stored>::solve_chebyshev(const double* B, double* X, double relative_tolerance,
                                                int max_iterations, const std::string& what) const {
  using Sums = std::array<double, K>;
  const Eigen::Index n = size();
  const Stored* inv_d = inv_diag_.data();
  R_.resize(static_cast<size_t>(S * n));
  P_.resize(static_cast<size_t>(S * n));
  Q_.resize(static_cast<size_t>(S * n));
  Stored* R0 = R_.data();
  Stored* Y0 = P_.data();  // y_k
  Stored* Y1 = Q_.data();  // y_{k−1}, overwritten by y_{k+1}
  // (A diagonal matrix has a one-point interval: a width of 1e-9 θ keeps the coefficients
  // finite; the first sweep then solves it.)
  const double theta = 0.5 * (lambda_max_ + lambda_min_);
  const double delta = std::max(0.5 * (lambda_max_ - lambda_min_), 1e-9 * theta);
  const double sigma1 = theta / delta;

  // r₀ = b − A x₀, y₁ = D⁻¹ r₀ / θ; sums ‖b‖², ‖r₀‖².
  const auto s0 = column_sums<K, 2>(
      n,
      [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 2>& s) {
        for (Eigen::Index i = i0; i < i1; ++i) {
          double ax[K];
          row_product<K, K, Ell>(i, X, ax);
          for (int c = K; c < S; ++c) R0[S * i + c] = Y0[S * i + c] = 0;  // the padding
          for (int c = 0; c < K; ++c) {
            const double b = B[K * i + c];
            const Stored r = static_cast<Stored>(b - ax[c]);
            R0[S * i + c] = r;
            Y0[S * i + c] = static_cast<Stored>(double(r) * double(inv_d[i]) / theta);
            s[0][c] += b * b;
            s[1][c] += double(r) * double(r);
          }
        }
      },
      product_weight<Ell>());
  Sums tol{};
  PcgStats stats;
  auto converged = [&](const Sums& rr) {
    bool all = true;
    stats.relative_residual = 0;
    for (int c = 0; c < K; ++c) {
      if (s0[0][c] == 0) continue;
      if (!std::isfinite(rr[c])) throw SolverError(what + ": Chebyshev iteration broke down (non-finite values)");
      stats.relative_residual = std::max(stats.relative_residual, std::sqrt(rr[c] / s0[0][c]));
      all = all && std::sqrt(rr[c]) <= tol[c];
    }
    return all;
  };
  for (int c = 0; c < K; ++c) {
    tol[c] = relative_tolerance * std::sqrt(s0[0][c]);
    if (s0[0][c] == 0)  // b = 0: the solution is 0 (and r₀ and y stay 0)
      for (Eigen::Index i = 0; i < n; ++i) {
        X[K * i + c] = 0;
        R0[S * i + c] = 0;
        Y0[S * i + c] = 0;
      }
  }
  if (converged(s0[1])) return stats;
  // x += y (the pass that ends a solve, or hands it to CG).
  auto add_correction = [&](const Stored* y) {
    parallel_for_blocks(
        n,
        [&](Eigen::Index i0, Eigen::Index i1) {
          double* __restrict x = X;
          for (Eigen::Index i = i0; i < i1; ++i)
            for (int c = 0; c < K; ++c) x[K * i + c] += double(y[S * i + c]);
        },
        K);
  };
  // Sweeps the rate promises: the error falls at least like 2 q^k with q = (√κ−1)/(√κ+1).
  const double kappa = lambda_max_ / lambda_min_, q = (std::sqrt(kappa) - 1) / (std::sqrt(kappa) + 1);
  const double reduction = std::max(relative_tolerance / std::max(stats.relative_residual, 1e-300), 1e-300);
  const int promised = static_cast<int>(std::ceil(std::log(reduction / 2) / std::log(q)));
  const int budget = std::min(max_iterations, 2 * std::max(promised, 1) + 4);
  double rho = 1 / sigma1;
  int it = 0;
  while (true) {
    if (++it > budget) {
      // Not the spectrum learnt: CG from here, learning it again (its residual now holds
      // what Chebyshev was slow on) for the solves after this one.
      add_correction(Y0);
      lambda_min_ = 0;
      const PcgStats cg = solve_layout<K, Ell, S>(B, X, relative_tolerance, max_iterations - it + 1, what);
      stats.iterations = it - 1 + cg.iterations;
      stats.relative_residual = cg.relative_residual;
      return stats;
    }
    const double rho_next = 1 / (2 * sigma1 - rho);
    const double c1 = rho_next * rho, c2 = 2 * rho_next / delta;
    rho = rho_next;
    // r = r₀ − A y_k, y_{k+1} = y_k + c₁ (y_k − y_{k−1}) + c₂ D⁻¹ r (y₀ = 0); sum ‖r‖².
    auto sweep = [&](auto first) {
      return column_sums<K, 1>(
          n,
          [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 1>& s) {
            const Stored* __restrict y = Y0;
            Stored* __restrict y_old = Y1;
            const Stored* __restrict r0 = R0;
            Sums rr{};
            if constexpr (S == 4 && Ell) {
              chebyshev_sweep_wide(i0, i1, ell_diag_.data(), ell_vals_.data(), ell_cols_.data(), inv_d, y, y_old, r0,
                                   c1, c2, decltype(first)::value, rr.data());
              s[0] = rr;
              return;
            }
            for (Eigen::Index i = i0; i < i1; ++i) {
              double a[K];
              row_product<K, S, Ell>(i, y, a);
              const double di = inv_d[i];
              for (int c = 0; c < K; ++c) {
                const Eigen::Index e = S * i + c;
                const double rc = double(r0[e]) - a[c], yc = y[e];
                const double previous = decltype(first)::value ? 0.0 : double(y_old[e]);
                y_old[e] = static_cast<Stored>(yc + c1 * (yc - previous) + c2 * di * rc);
                rr[c] += rc * rc;
              }
            }
            s[0] = rr;
          },
          product_weight<Ell>());
    };
    const auto s1 = it == 1 ? sweep(std::true_type{}) : sweep(std::false_type{});
    if (converged(s1[0])) break;  // at y_k, which the sweep only read
    std::swap(Y0, Y1);
  }
  add_correction(Y0);
  stats.iterations = it;
  return stats;
}

template class BasicBlockPcg<double>;
template class BasicBlockPcg<float>;

}  // namespace msmesh::detail
