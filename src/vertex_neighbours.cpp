#include "vertex_neighbours.h"

#include <algorithm>

#include "parallel.h"

namespace msmesh::detail {

// Each face's three edges in both directions, bucketed by vertex (so each vertex's slots hold
// twice its face count), then each bucket sorted and its duplicates (an edge seen from both of
// its faces) dropped.
VertexNeighbours::VertexNeighbours(const Eigen::MatrixXi& F, Eigen::Index nv)
    : start(static_cast<std::size_t>(nv) + 1, 0), count(static_cast<std::size_t>(nv)) {
  for (Eigen::Index i = 0; i < F.size(); ++i) start[static_cast<std::size_t>(F.data()[i]) + 1] += 2;
  for (std::size_t i = 0; i + 1 < start.size(); ++i) start[i + 1] += start[i];
  nbr.resize(static_cast<std::size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      nbr[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
      nbr[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
    }
  parallel_for(
      nv,
      [&](Eigen::Index i) {
        int* first = nbr.data() + start[static_cast<std::size_t>(i)];
        int* last = nbr.data() + start[static_cast<std::size_t>(i) + 1];
        std::sort(first, last);
        count[static_cast<std::size_t>(i)] = static_cast<int>(std::unique(first, last) - first);
      },
      4);
}

}  // namespace msmesh::detail
