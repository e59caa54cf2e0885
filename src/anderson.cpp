#include "anderson.h"

#include <Eigen/Dense>
#include <array>

#include "parallel.h"

namespace msmesh::detail {

namespace {

// The Gram matrix ⟨df_a, df_b⟩ and the right-hand side ⟨df_a, f⟩ of the least-squares problem,
// in one pass over the rows (rather than one per product), summed in fixed blocks: the same
// sums at any thread count.
void normal_equations(const std::vector<RowMatrixX3>& df, int m, const RowMatrixX3& f, Eigen::MatrixXd& gram,
                      Eigen::VectorXd& rhs) {
  const Eigen::Index n = f.rows(), nb = (n + kBlock - 1) / kBlock;
  const int sums = m + m * (m + 1) / 2;
  std::vector<double> partial(static_cast<size_t>(nb * sums), 0.0);
  parallel_for_blocks(
      n,
      [&](Eigen::Index i0, Eigen::Index i1) {
        double* s = partial.data() + (i0 / kBlock) * sums;
        for (Eigen::Index i = i0; i < i1; ++i) {
          int k = 0;
          for (int a = 0; a < m; ++a) {
            const Eigen::RowVector3d da = df[static_cast<size_t>(a)].row(i);
            s[k++] += da.dot(f.row(i));
            for (int b = 0; b <= a; ++b) s[k++] += da.dot(df[static_cast<size_t>(b)].row(i));
          }
        }
      },
      sums);
  std::vector<double> total(static_cast<size_t>(sums), 0.0);
  for (Eigen::Index b = 0; b < nb; ++b)
    for (int k = 0; k < sums; ++k) total[static_cast<size_t>(k)] += partial[static_cast<size_t>(b * sums + k)];
  gram.resize(m, m);
  rhs.resize(m);
  int k = 0;
  for (int a = 0; a < m; ++a) {
    rhs(a) = total[static_cast<size_t>(k++)];
    for (int b = 0; b <= a; ++b) gram(a, b) = gram(b, a) = total[static_cast<size_t>(k++)];
  }
}

}  // namespace

void AndersonAcceleration::step(const RowMatrixX3& g, RowMatrixX3& x) {
  const Eigen::Index n = g.rows();
  if (has_previous_) {
    if (static_cast<int>(df_.size()) < depth_ && next_ == static_cast<int>(df_.size())) {
      df_.emplace_back(n, 3);
      dg_.emplace_back(n, 3);
    }
    RowMatrixX3& df = df_[static_cast<size_t>(next_)];
    RowMatrixX3& dg = dg_[static_cast<size_t>(next_)];
    parallel_for_blocks(
        n,
        [&](Eigen::Index i0, Eigen::Index i1) {
          for (Eigen::Index i = i0; i < i1; ++i) {
            const Eigen::RowVector3d f = g.row(i) - x.row(i);
            df.row(i) = f - f_previous_.row(i);
            dg.row(i) = g.row(i) - g_previous_.row(i);
            f_previous_.row(i) = f;
            g_previous_.row(i) = g.row(i);
          }
        },
        3);
    next_ = (next_ + 1) % depth_;
    count_ = std::min(count_ + 1, depth_);
  } else {
    f_previous_ = g - x;
    g_previous_ = g;
    has_previous_ = true;
  }
  if (count_ == 0) {
    x = g;
    return;
  }
  // θ from the normal equations of the small least-squares problem, slightly regularised
  // (the Δf become nearly parallel close to convergence).
  const int m = count_;
  Eigen::MatrixXd gram;
  Eigen::VectorXd rhs;
  normal_equations(df_, m, f_previous_, gram, rhs);
  gram.diagonal().array() += 1e-10 * gram.diagonal().maxCoeff() + 1e-300;
  const Eigen::VectorXd theta = gram.ldlt().solve(rhs);
  if (!theta.allFinite()) {  // a degenerate history: take the plain step and start again
    x = g;
    restart();
    return;
  }
  parallel_for_blocks(
      n,
      [&](Eigen::Index i0, Eigen::Index i1) {
        for (Eigen::Index i = i0; i < i1; ++i) {
          Eigen::RowVector3d r = g.row(i);
          for (int a = 0; a < m; ++a) r -= theta(a) * dg_[static_cast<size_t>(a)].row(i);
          x.row(i) = r;
        }
      },
      3 * m);
}

}  // namespace msmesh::detail
