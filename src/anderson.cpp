#include "anderson.h"

#include <Eigen/Dense>
#include <array>

#include "parallel.h"

namespace msmesh::detail {

namespace {

// ⟨a, b⟩ over all rows and columns, in fixed blocks (the same sum at any thread count).
double dot(const RowMatrixX3& a, const RowMatrixX3& b) {
  return deterministic_sums<1>(a.rows(), [&](Eigen::Index i0, Eigen::Index i1, std::array<double, 1>& s) {
    for (Eigen::Index i = i0; i < i1; ++i) s[0] += a.row(i).dot(b.row(i));
  })[0];
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
    parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
      for (Eigen::Index i = i0; i < i1; ++i) {
        const Eigen::RowVector3d f = g.row(i) - x.row(i);
        df.row(i) = f - f_previous_.row(i);
        dg.row(i) = g.row(i) - g_previous_.row(i);
        f_previous_.row(i) = f;
        g_previous_.row(i) = g.row(i);
      }
    });
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
  Eigen::MatrixXd gram(m, m);
  Eigen::VectorXd rhs(m);
  for (int a = 0; a < m; ++a) {
    rhs(a) = dot(df_[static_cast<size_t>(a)], f_previous_);
    for (int b = 0; b <= a; ++b)
      gram(a, b) = gram(b, a) = dot(df_[static_cast<size_t>(a)], df_[static_cast<size_t>(b)]);
  }
  gram.diagonal().array() += 1e-10 * gram.diagonal().maxCoeff() + 1e-300;
  const Eigen::VectorXd theta = gram.ldlt().solve(rhs);
  if (!theta.allFinite()) {  // a degenerate history: take the plain step and start again
    x = g;
    restart();
    return;
  }
  parallel_for_blocks(n, [&](Eigen::Index i0, Eigen::Index i1) {
    for (Eigen::Index i = i0; i < i1; ++i) {
      Eigen::RowVector3d r = g.row(i);
      for (int a = 0; a < m; ++a) r -= theta(a) * dg_[static_cast<size_t>(a)].row(i);
      x.row(i) = r;
    }
  });
}

}  // namespace msmesh::detail
