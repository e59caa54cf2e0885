#include "tree_solve.h"

#include <cholmod.h>

#include <algorithm>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace msmesh::detail {

namespace {

// Below this many entries in L a solve takes about a millisecond or less, and waking the
// second thread (twice per solve, passive waits) costs more than it saves: Fandisk's
// vertex update (487K entries) took 1.0 ms serial, 1.2 ms on two threads; the Cone's
// (1.8M) 8.8 → 4.5 ms, its N-step (0.9M) 4.5 → 2.7 ms.
constexpr double kMinParallelEntries = 600000;

}  // namespace

int tree_threads() {
#ifdef _OPENMP
  return std::min(2, omp_get_max_threads());
#else
  return 1;
#endif
}

TreeSplit split_elimination_tree(const std::vector<int>& parent, const std::vector<double>& cost_in, double min_total) {
  const size_t n = parent.size();
  TreeSplit split;
  // Subtree costs and sizes; each subtree must be the column range [j − size + 1, j].
  std::vector<int> size(n, 1);
  std::vector<double> cost(cost_in);
  double total = 0;
  bool postordered = true;
  for (size_t j = 0; j < n; ++j) {
    total += cost_in[j];
    if (parent[j] >= 0 && parent[j] <= static_cast<int>(j)) postordered = false;
  }
  for (size_t j = 0; j < n && postordered; ++j)
    if (parent[j] >= 0) {
      cost[static_cast<size_t>(parent[j])] += cost[j];
      size[static_cast<size_t>(parent[j])] += size[j];
    }
  for (size_t j = 0; j < n && postordered; ++j) {
    const int first = static_cast<int>(j) - size[j] + 1;
    if (first < 0) postordered = false;
    if (parent[j] >= 0 && first < parent[j] - size[static_cast<size_t>(parent[j])] + 1) postordered = false;
  }
  std::vector<char> in_set(n, 0);
  if (postordered && total >= min_total) {
    std::vector<int> child_start(n + 1, 0), children(n);
    for (size_t j = 0; j < n; ++j)
      if (parent[j] >= 0) ++child_start[static_cast<size_t>(parent[j]) + 1];
    for (size_t j = 0; j < n; ++j) child_start[j + 1] += child_start[j];
    {
      std::vector<int> fill(child_start.begin(), child_start.end() - 1);
      for (size_t j = 0; j < n; ++j)
        if (parent[j] >= 0) children[static_cast<size_t>(fill[static_cast<size_t>(parent[j])]++)] = static_cast<int>(j);
    }
    // Start from the roots; split the heaviest subtree (its root joins the top) until the
    // subtrees fill two sets evenly (greedy, heaviest first) or the top gets too heavy.
    std::vector<int> candidates;
    for (size_t j = 0; j < n; ++j)
      if (parent[j] < 0) candidates.push_back(static_cast<int>(j));
    const auto heavier = [&](int a, int b) {
      const double ca = cost[static_cast<size_t>(a)], cb = cost[static_cast<size_t>(b)];
      return ca > cb || (ca == cb && a < b);
    };
    double top_cost = 0, best_time = total;
    std::vector<int> best[2];
    for (int round = 0; round < 4096 && !candidates.empty(); ++round) {
      std::sort(candidates.begin(), candidates.end(), heavier);
      double load[2] = {0, 0};
      std::vector<int> sets[2];
      for (int r : candidates) {
        const int b = load[1] < load[0] ? 1 : 0;
        load[b] += cost[static_cast<size_t>(r)];
        sets[b].push_back(r);
      }
      const double time = top_cost + std::max(load[0], load[1]);
      if (time < best_time) {
        best_time = time;
        best[0] = sets[0];
        best[1] = sets[1];
      }
      if (top_cost > 0.3 * total || std::max(load[0], load[1]) <= 0.51 * (load[0] + load[1])) break;
      const int heavy = candidates.front();
      candidates.erase(candidates.begin());
      top_cost += cost_in[static_cast<size_t>(heavy)];
      for (int c = child_start[static_cast<size_t>(heavy)]; c < child_start[static_cast<size_t>(heavy) + 1]; ++c)
        candidates.push_back(children[static_cast<size_t>(c)]);
    }
    if (best_time < 0.8 * total)
      for (int s = 0; s < 2; ++s) {
        for (int r : best[s]) {
          const TreeSplit::Range range{r - size[static_cast<size_t>(r)] + 1, r + 1};
          split.sets[s].push_back(range);
          std::fill(in_set.begin() + range.begin, in_set.begin() + range.end, 1);
          split.parallel_share += cost[static_cast<size_t>(r)] / total;
        }
        std::sort(split.sets[s].begin(), split.sets[s].end(),
                  [](const TreeSplit::Range& a, const TreeSplit::Range& b) { return a.begin < b.begin; });
      }
  }
  for (size_t j = 0; j < n; ++j)
    if (!in_set[j]) split.top.push_back(static_cast<int>(j));
  return split;
}

TreeSolve::TreeSolve(const cholmod_factor_struct* L) {
  if (!L || L->is_super || !L->is_ll || L->xtype != CHOLMOD_REAL || L->itype != CHOLMOD_INT || L->minor < L->n ||
      !L->Perm || !L->nz)
    return;
  valid_ = true;
  n_ = static_cast<int>(L->n);
  Lp_ = static_cast<const int*>(L->p);
  Li_ = static_cast<const int*>(L->i);
  Lnz_ = static_cast<const int*>(L->nz);
  Lx_ = static_cast<const double*>(L->x);
  perm_ = static_cast<const int*>(L->Perm);
  work_.resize(3 * static_cast<size_t>(n_));
  const size_t n = static_cast<size_t>(n_);
  // Elimination tree from L: the first off-diagonal row of column j (rows are sorted).
  std::vector<int> parent(n, -1);
  std::vector<double> cost(n);
  for (size_t j = 0; j < n; ++j) {
    cost[j] = Lnz_[j];
    if (Lnz_[j] > 1) parent[j] = Li_[Lp_[j] + 1];
  }
  TreeSplit split = split_elimination_tree(parent, cost, kMinParallelEntries);
  sets_[0] = std::move(split.sets[0]);
  sets_[1] = std::move(split.sets[1]);
  top_ = std::move(split.top);
  parallel_share_ = split.parallel_share;
  top_slot_.assign(n, -1);
  for (size_t t = 0; t < top_.size(); ++t) top_slot_[static_cast<size_t>(top_[t])] = static_cast<int>(t);
  for (auto& b : buffer_) b.assign(3 * top_.size(), 0.0);
}

void TreeSolve::forward(double* y) const {
  // Column j: y_j /= L_jj, then y_i −= L_ij y_j for the rows i below; rows from `end` on
  // (ancestors outside j's set, all in the top) go to `buf` instead, by their top slot.
  const auto column = [&](int j, int end, double* buf) {
    const int p0 = Lp_[j], p1 = p0 + Lnz_[j];
    const double d = Lx_[p0];
    double* yj = y + 3 * static_cast<size_t>(j);
    const double x0 = yj[0] / d, x1 = yj[1] / d, x2 = yj[2] / d;
    yj[0] = x0;
    yj[1] = x1;
    yj[2] = x2;
    int q = p0 + 1;
    for (; q < p1 && Li_[q] < end; ++q) {
      double* yi = y + 3 * static_cast<size_t>(Li_[q]);
      const double l = Lx_[q];
      yi[0] -= l * x0;
      yi[1] -= l * x1;
      yi[2] -= l * x2;
    }
    for (; q < p1; ++q) {
      double* bi = buf + 3 * static_cast<size_t>(top_slot_[static_cast<size_t>(Li_[q])]);
      const double l = Lx_[q];
      bi[0] += l * x0;
      bi[1] += l * x1;
      bi[2] += l * x2;
    }
  };
  if (!sets_[0].empty() || !sets_[1].empty()) {
    // The two sets at once, each with its own buffer for the top rows.
#pragma omp parallel for num_threads(tree_threads()) schedule(static, 1)
    for (int s = 0; s < 2; ++s) {
      std::fill(buffer_[s].begin(), buffer_[s].end(), 0.0);
      for (const Range& r : sets_[s])
        for (int j = r.begin; j < r.end; ++j) column(j, r.end, buffer_[s].data());
    }
    for (size_t t = 0; t < top_.size(); ++t) {
      double* yt = y + 3 * static_cast<size_t>(top_[t]);
      for (int c = 0; c < 3; ++c)
        yt[c] = (yt[c] - buffer_[0][3 * t + static_cast<size_t>(c)]) - buffer_[1][3 * t + static_cast<size_t>(c)];
    }
  }
  for (const int j : top_) column(j, n_, nullptr);  // the top's rows are all in the top
}

void TreeSolve::backward(double* x) const {
  auto column = [&](int j) {
    const int p0 = Lp_[j], p1 = p0 + Lnz_[j];
    double s0 = x[3 * static_cast<size_t>(j)], s1 = x[3 * static_cast<size_t>(j) + 1],
           s2 = x[3 * static_cast<size_t>(j) + 2];
    for (int q = p0 + 1; q < p1; ++q) {
      const double* xi = x + 3 * static_cast<size_t>(Li_[q]);
      const double l = Lx_[q];
      s0 -= l * xi[0];
      s1 -= l * xi[1];
      s2 -= l * xi[2];
    }
    const double d = Lx_[p0];
    x[3 * static_cast<size_t>(j)] = s0 / d;
    x[3 * static_cast<size_t>(j) + 1] = s1 / d;
    x[3 * static_cast<size_t>(j) + 2] = s2 / d;
  };
  for (auto it = top_.rbegin(); it != top_.rend(); ++it) column(*it);
  if (sets_[0].empty() && sets_[1].empty()) return;
#pragma omp parallel for num_threads(tree_threads()) schedule(static, 1)
  for (int s = 0; s < 2; ++s)
    for (auto r = sets_[s].rbegin(); r != sets_[s].rend(); ++r)
      for (int j = r->end - 1; j >= r->begin; --j) column(j);
}

void TreeSolve::solve(const RowMatrixX3& B, RowMatrixX3& X) const {
  // L Lᵀ = Pᵀ A P with P from Perm: A x = b ⇔ L Lᵀ (Pᵀx) = Pᵀb.
  double* w = work_.data();
  for (int k = 0; k < n_; ++k)
    for (int c = 0; c < 3; ++c) w[3 * static_cast<size_t>(k) + static_cast<size_t>(c)] = B(perm_[k], c);
  forward(w);
  backward(w);
  X.resize(n_, 3);
  for (int k = 0; k < n_; ++k)
    for (int c = 0; c < 3; ++c) X(perm_[k], c) = w[3 * static_cast<size_t>(k) + static_cast<size_t>(c)];
}

}  // namespace msmesh::detail
