#include "pcg.h"

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <sstream>
#include <vector>

#include "msmesh/errors.h"
#include "parallel.h"

namespace msmesh::detail {

namespace {

// Sums of three columns, K of them at once, in a fixed order (parallel.h).
template <int K, class Body>
std::array<std::array<double, 3>, K> column_sums(Eigen::Index n, Body&& body) {
  const auto flat = deterministic_sums<3 * K>(n, [&](Eigen::Index i0, Eigen::Index i1, std::array<double, 3 * K>& s) {
    std::array<std::array<double, 3>, K> t{};
    body(i0, i1, t);
    for (int k = 0; k < K; ++k)
      for (int c = 0; c < 3; ++c) s[3 * k + c] += t[k][c];
  });
  std::array<std::array<double, 3>, K> out{};
  for (int k = 0; k < K; ++k)
    for (int c = 0; c < 3; ++c) out[k][c] = flat[3 * k + c];
  return out;
}
using Sums = std::array<double, 3>;

}  // namespace

RowMatrixX3 to_rows(const Eigen::MatrixXd& M) { return RowMatrixX3(M); }

namespace {

// Reverse Cuthill–McKee order of the graph of the symmetric matrix A (new position → old
// row): neighbours end up close in memory, so the gathers of the matrix–vector product hit
// the cache. Scanned meshes often list their vertices in scan order, not surface order (the
// Cone's faces span 5800 vertex indices on median); there this makes CG sweeps ~2× cheaper.
std::vector<int> reverse_cuthill_mckee(const RowSparse& A) {
  const int n = static_cast<int>(A.rows());
  std::vector<int> degree(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) degree[static_cast<size_t>(i)] = A.outerIndexPtr()[i + 1] - A.outerIndexPtr()[i];
  std::vector<int> order;
  order.reserve(static_cast<size_t>(n));
  std::vector<char> seen(static_cast<size_t>(n), 0);
  std::vector<int> nbrs;
  // Breadth-first from `start`, appending to `out`; returns the last vertex reached with the
  // smallest degree in the last level (a pseudo-peripheral vertex for the next start).
  auto bfs = [&](int start, std::vector<int>& out, std::vector<char>& mark) {
    size_t head = out.size();
    out.push_back(start);
    mark[static_cast<size_t>(start)] = 1;
    size_t level_begin = head;
    while (head < out.size()) {
      const size_t level_end = out.size();
      level_begin = head;
      for (; head < level_end; ++head) {
        const int u = out[head];
        nbrs.clear();
        for (RowSparse::InnerIterator it(A, u); it; ++it) {
          const int w = static_cast<int>(it.col());
          if (!mark[static_cast<size_t>(w)]) {
            mark[static_cast<size_t>(w)] = 1;
            nbrs.push_back(w);
          }
        }
        std::sort(nbrs.begin(), nbrs.end(), [&](int a, int b) {
          return degree[static_cast<size_t>(a)] != degree[static_cast<size_t>(b)]
                     ? degree[static_cast<size_t>(a)] < degree[static_cast<size_t>(b)]
                     : a < b;
        });
        out.insert(out.end(), nbrs.begin(), nbrs.end());
      }
    }
    int best = out[level_begin];
    for (size_t i = level_begin; i < out.size(); ++i)
      if (degree[static_cast<size_t>(out[i])] < degree[static_cast<size_t>(best)]) best = out[i];
    return best;
  };
  std::vector<int> scratch;
  std::vector<char> scratch_mark;
  for (int s = 0; s < n; ++s) {
    if (seen[static_cast<size_t>(s)]) continue;
    // Two sweeps to find a far start vertex of this component, then the ordering sweep.
    int start = s;
    for (int sweep = 0; sweep < 2; ++sweep) {
      scratch.clear();
      scratch_mark = seen;
      start = bfs(start, scratch, scratch_mark);
    }
    bfs(start, order, seen);
  }
  std::reverse(order.begin(), order.end());
  return order;
}

}  // namespace

BlockPcg::BlockPcg(const Eigen::SparseMatrix<double>& A) {
  const RowSparse A0(A);
  const Eigen::Index n = A0.rows();
  perm_ = reverse_cuthill_mckee(A0);
  std::vector<int> inverse(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) inverse[static_cast<size_t>(perm_[static_cast<size_t>(i)])] = static_cast<int>(i);
  // A_ = P A Pᵀ in compressed row-major form, columns sorted within each row.
  A_.resize(n, n);
  A_.resizeNonZeros(A0.nonZeros());
  int* outer = A_.outerIndexPtr();
  int* inner = A_.innerIndexPtr();
  double* val = A_.valuePtr();
  outer[0] = 0;
  std::vector<std::pair<int, double>> row;
  for (Eigen::Index i = 0; i < n; ++i) {
    row.clear();
    for (RowSparse::InnerIterator it(A0, perm_[static_cast<size_t>(i)]); it; ++it)
      row.emplace_back(inverse[static_cast<size_t>(it.col())], it.value());
    std::sort(row.begin(), row.end());
    int k = outer[i];
    for (const auto& [c, v] : row) {
      inner[k] = c;
      val[k++] = v;
    }
    outer[i + 1] = k;
  }
  inv_diag_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    double d = 0;
    for (RowSparse::InnerIterator it(A_, i); it; ++it)
      if (it.col() == i) d += it.value();
    if (!(d > 0) || !std::isfinite(d)) {
      std::ostringstream os;
      os << "conjugate gradients: diagonal entry " << perm_[static_cast<size_t>(i)] << " = " << d
         << " is not positive";
      throw SolverError(os.str());
    }
    inv_diag_(i) = 1.0 / d;
  }
}

PcgStats BlockPcg::solve(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance, int max_iterations,
                         const std::string& what) const {
  const Eigen::Index n = A_.rows();
  Bp_.resize(n, 3);
  Xp_.resize(n, 3);
  parallel_for(n, [&](Eigen::Index i) {
    const Eigen::Index o = perm_[static_cast<size_t>(i)];
    Bp_.row(i) = B.row(o);
    Xp_.row(i) = X.row(o);
  });
  const PcgStats st = solve_permuted(Bp_, Xp_, relative_tolerance, max_iterations, what);
  parallel_for(n, [&](Eigen::Index i) { X.row(perm_[static_cast<size_t>(i)]) = Xp_.row(i); });
  return st;
}

PcgStats BlockPcg::solve_permuted(const RowMatrixX3& B, RowMatrixX3& X, double relative_tolerance,
                                  int max_iterations, const std::string& what) const {
  const Eigen::Index n = A_.rows();
  const int* outer = A_.outerIndexPtr();
  const int* inner = A_.innerIndexPtr();
  const double* val = A_.valuePtr();
  const double* inv_d = inv_diag_.data();
  // Work space kept between calls (no allocation, no page faults in the iterations).
  R_.resize(n, 3);
  P_.resize(n, 3);
  Q_.resize(n, 3);
  RowMatrixX3 &R = R_, &P = P_, &Q = Q_;

  // r = b − A x, p = D⁻¹ r; sums: ‖b‖², r·D⁻¹r, ‖r‖².
  const auto s0 = column_sums<3>(n, [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 3>& s) {
    for (Eigen::Index i = i0; i < i1; ++i) {
      double ax[3] = {0, 0, 0};
      for (int j = outer[i]; j < outer[i + 1]; ++j)
        for (int c = 0; c < 3; ++c) ax[c] += val[j] * X(inner[j], c);
      for (int c = 0; c < 3; ++c) {
        const double r = B(i, c) - ax[c], z = r * inv_d[i];
        R(i, c) = r;
        P(i, c) = z;
        s[0][c] += B(i, c) * B(i, c);
        s[1][c] += r * z;
        s[2][c] += r * r;
      }
    }
  });
  Sums tol{}, rz = s0[1];
  std::array<bool, 3> done{};
  PcgStats stats;
  for (int c = 0; c < 3; ++c) {
    tol[c] = relative_tolerance * std::sqrt(s0[0][c]);
    if (s0[0][c] == 0) {  // b = 0: the solution is 0
      X.col(c).setZero();
      done[c] = true;
      continue;
    }
    done[c] = std::sqrt(s0[2][c]) <= tol[c];
    if (!done[c]) stats.relative_residual = std::max(stats.relative_residual, std::sqrt(s0[2][c] / s0[0][c]));
  }
  auto all_done = [&] { return done[0] && done[1] && done[2]; };
  for (int c = 0; c < 3; ++c)
    if (done[c]) P.col(c).setZero();

  int it = 0;
  while (!all_done()) {
    if (++it > max_iterations) {
      std::ostringstream os;
      os << what << ": conjugate gradients did not reach relative residual " << relative_tolerance << " in "
         << max_iterations << " iterations (at " << stats.relative_residual << ")";
      throw SolverError(os.str());
    }
    // q = A p, p·q.
    const double* Pp = P.data();
    double* Qp = Q.data();
    const auto s1 = column_sums<1>(n, [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 1>& s) {
      const double* __restrict p = Pp;
      double* __restrict q = Qp;
      double s_0 = 0, s_1 = 0, s_2 = 0;
      for (Eigen::Index i = i0; i < i1; ++i) {
        double a0 = 0, a1 = 0, a2 = 0;
        const int j1 = outer[i + 1];
        for (int j = outer[i]; j < j1; ++j) {
          const double a = val[j];
          const double* pj = p + 3 * static_cast<Eigen::Index>(inner[j]);
          a0 += a * pj[0];
          a1 += a * pj[1];
          a2 += a * pj[2];
        }
        q[3 * i] = a0;
        q[3 * i + 1] = a1;
        q[3 * i + 2] = a2;
        s_0 += p[3 * i] * a0;
        s_1 += p[3 * i + 1] * a1;
        s_2 += p[3 * i + 2] * a2;
      }
      s[0] = {s_0, s_1, s_2};
    });
    Sums alpha{};
    for (int c = 0; c < 3; ++c) alpha[c] = done[c] ? 0.0 : rz[c] / s1[0][c];
    // x += α p, r −= α q; sums: r·D⁻¹r, ‖r‖².
    double* Xp = X.data();
    double* Rp = R.data();
    const double al0 = alpha[0], al1 = alpha[1], al2 = alpha[2];
    const auto s2 = column_sums<2>(n, [&](Eigen::Index i0, Eigen::Index i1, std::array<Sums, 2>& s) {
      double* __restrict x = Xp;
      double* __restrict r = Rp;
      const double* __restrict p = Pp;
      const double* __restrict q = Qp;
      const double* __restrict id = inv_d;
      double rz0 = 0, rz1 = 0, rz2 = 0, rr0 = 0, rr1 = 0, rr2 = 0;
      for (Eigen::Index i = i0; i < i1; ++i) {
        const Eigen::Index b = 3 * i;
        x[b] += al0 * p[b];
        x[b + 1] += al1 * p[b + 1];
        x[b + 2] += al2 * p[b + 2];
        const double r0 = r[b] - al0 * q[b], r1 = r[b + 1] - al1 * q[b + 1], r2 = r[b + 2] - al2 * q[b + 2];
        r[b] = r0;
        r[b + 1] = r1;
        r[b + 2] = r2;
        const double di = id[i];
        rz0 += r0 * r0 * di;
        rz1 += r1 * r1 * di;
        rz2 += r2 * r2 * di;
        rr0 += r0 * r0;
        rr1 += r1 * r1;
        rr2 += r2 * r2;
      }
      s[0] = {rz0, rz1, rz2};
      s[1] = {rr0, rr1, rr2};
    });
    Sums beta{};
    stats.relative_residual = 0;
    for (int c = 0; c < 3; ++c) {
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
    }
    if (all_done()) break;
    // p = D⁻¹ r + β p (0 for the columns that are done).
    Sums keep{};
    for (int c = 0; c < 3; ++c) keep[c] = done[c] ? 0.0 : 1.0;
    double* Pw = P.data();
    const double k0 = keep[0], k1 = keep[1], k2 = keep[2], b0 = beta[0], b1 = beta[1], b2 = beta[2];
    parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
      double* __restrict p = Pw;
      const double* __restrict r = Rp;
      for (Eigen::Index i = i0; i < i1; ++i) {
        const double di = inv_d[i];
        p[3 * i] = k0 * (r[3 * i] * di + b0 * p[3 * i]);
        p[3 * i + 1] = k1 * (r[3 * i + 1] * di + b1 * p[3 * i + 1]);
        p[3 * i + 2] = k2 * (r[3 * i + 2] * di + b2 * p[3 * i + 2]);
      }
    });
  }
  stats.iterations = it;
  return stats;
}

}  // namespace msmesh::detail
