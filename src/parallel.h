// Internal: deterministic parallel loops (the results must not depend on the thread count).
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <vector>

namespace msmesh::detail {

/// Rows per block. Reductions form one partial sum per block and add the partials in block
/// order, so a sum is the same whatever the number of threads; loops over fewer than
/// kParallelMin rows run on one thread (below that the fork/join costs about as much as the
/// work it shares, and far more when the machine is busy), outside any parallel construct: the
/// first construct starts the OpenMP runtime, and LLVM's registers itself in a shared-memory
/// file, which a file-size limit refuses (small jobs then run without the runtime at all).
constexpr Eigen::Index kBlock = 2048;
constexpr Eigen::Index kParallelMin = 16 * kBlock;

/// Runs body(begin, end, sums) over fixed blocks of [0, n) and returns the K sums, added in
/// block order. body adds its block's contributions to sums (zero-initialised). `row_weight`
/// as for parallel_for below.
template <int K, class Body>
std::array<double, K> deterministic_sums(Eigen::Index n, Body&& body, Eigen::Index row_weight = 1) {
  const Eigen::Index nb = (n + kBlock - 1) / kBlock;
  std::vector<std::array<double, K>> partial(static_cast<size_t>(nb));
  const auto block = [&](Eigen::Index b) {
    std::array<double, K> s{};
    body(b * kBlock, std::min(n, (b + 1) * kBlock), s);
    partial[static_cast<size_t>(b)] = s;
  };
  if (n * row_weight >= kParallelMin) {
#pragma omp parallel for schedule(static)
    for (Eigen::Index b = 0; b < nb; ++b) block(b);
  } else {
    for (Eigen::Index b = 0; b < nb; ++b) block(b);
  }
  std::array<double, K> total{};
  for (const auto& s : partial)
    for (int k = 0; k < K; ++k) total[k] += s[k];
  return total;
}

/// Runs body(i) for i in [0, n), in parallel when n is large enough; `row_weight` counts a
/// row as that many simple rows (a vertex-update matrix row of ~70 entries is worth ~17).
template <class Body>
void parallel_for(Eigen::Index n, Body&& body, Eigen::Index row_weight = 1) {
  if (n * row_weight < kParallelMin) {
    for (Eigen::Index i = 0; i < n; ++i) body(i);
    return;
  }
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < n; ++i) body(i);
}

/// Runs body(begin, end) over fixed blocks of [0, n), in parallel when n is large enough;
/// `row_weight` as for parallel_for (a row of three columns is worth three).
template <class Body>
void parallel_for_blocks(Eigen::Index n, Body&& body, Eigen::Index row_weight = 1) {
  const Eigen::Index nb = (n + kBlock - 1) / kBlock;
  if (n * row_weight < kParallelMin) {
    for (Eigen::Index b = 0; b < nb; ++b) body(b * kBlock, std::min(n, (b + 1) * kBlock));
    return;
  }
#pragma omp parallel for schedule(static)
  for (Eigen::Index b = 0; b < nb; ++b) body(b * kBlock, std::min(n, (b + 1) * kBlock));
}

}  // namespace msmesh::detail
