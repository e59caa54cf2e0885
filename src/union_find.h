// Internal: union-find (disjoint sets) with path halving, for connected components.
#pragma once
#include <cstddef>
#include <numeric>
#include <vector>

namespace msmesh::detail {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace msmesh::detail
