// Internal: union-find (disjoint sets) with path halving, for connected components.
#pragma once
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace msmesh::detail {

struct UnionFind {
  std::vector<int> parent, size;
  explicit UnionFind(std::size_t n) : parent(n), size(n, 1) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  /// Joins the sets of a and b, the smaller under the larger (trees stay shallow).
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size[a] > size[b]) std::swap(a, b);
    parent[a] = b;
    size[b] += size[a];
  }
};

}  // namespace msmesh::detail
