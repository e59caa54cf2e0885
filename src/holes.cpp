// Hole finding (holes.h): the boundary loops of a mesh and the outer-boundary rule.
#include "msmesh/holes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/topology.h"
#include "union_find.h"

namespace msmesh {

using detail::UnionFind;

std::vector<Hole> find_holes(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "find holes");
  std::vector<Hole> holes;
  if (F.rows() == 0) return holes;
  const Eigen::Index nv = V.rows();
  const Topology topo = build_topology(F, nv);
  double h = mean_edge_length(V, F);
  if (!(h > 0)) h = 1;

  // Boundary half-edges, directed against their face (the hole's direction).
  std::vector<std::pair<int, int>> half;  // (from, to)
  std::vector<int> half_face;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    if (topo.edge_face_count(e) != 1) continue;
    const int f = topo.edge_faces(e, 0);
    int k = 0;
    while (topo.face_edges(f, k) != e) ++k;
    half.emplace_back(F(f, (k + 2) % 3), F(f, (k + 1) % 3));
    half_face.push_back(f);
  }
  if (half.empty()) return holes;

  std::vector<std::vector<int>> out(static_cast<size_t>(nv));
  std::vector<int> in_degree(static_cast<size_t>(nv), 0);
  UnionFind uf(static_cast<size_t>(nv));
  for (size_t i = 0; i < half.size(); ++i) {
    out[half[i].first].push_back(static_cast<int>(i));
    ++in_degree[half[i].second];
    uf.unite(half[i].first, half[i].second);
  }
  // Group half-edges by connected boundary; order groups by their smallest vertex.
  std::unordered_map<int, std::vector<int>> groups;
  for (size_t i = 0; i < half.size(); ++i) groups[uf.find(half[i].first)].push_back(static_cast<int>(i));
  std::vector<std::pair<int, std::vector<int>>> ordered;  // (smallest vertex, half-edges)
  for (auto& [root, hs] : groups) {
    (void)root;
    int vmin = std::numeric_limits<int>::max();
    for (int i : hs) vmin = std::min({vmin, half[i].first, half[i].second});
    ordered.emplace_back(vmin, std::move(hs));
  }
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

  int ncomp = 0;
  const Eigen::VectorXi comp = face_components(topo, &ncomp);
  std::vector<bool> used(half.size(), false);
  for (auto& [vmin, hs] : ordered) {
    Hole hole;
    hole.edges = static_cast<int>(hs.size());
    hole.component = comp(half_face[hs.front()]);
    for (int i : hs) {
      const int a = half[i].first;
      if (hole.simple && (out[a].size() != 1 || in_degree[a] != 1)) {
        hole.simple = false;
        hole.touching_vertex = a;
      }
      hole.length += (V.row(half[i].first) - V.row(half[i].second)).norm() / h;
    }
    // The closed walk (Hierholzer), starting at the smallest vertex that has an outgoing
    // half-edge; for a simple loop this is just the loop.
    int start = -1;
    for (int i : hs)
      if (start < 0 || half[i].first < start) start = half[i].first;
    std::vector<int> stack{start}, walk;
    std::unordered_map<int, size_t> next_out;
    while (!stack.empty()) {
      const int u = stack.back();
      size_t& k = next_out[u];
      while (k < out[u].size() && used[out[u][k]]) ++k;
      if (k < out[u].size()) {
        used[out[u][k]] = true;
        stack.push_back(half[out[u][k]].second);
      } else {
        walk.push_back(u);
        stack.pop_back();
      }
    }
    std::reverse(walk.begin(), walk.end());
    if (walk.size() > 1 && walk.front() == walk.back()) walk.pop_back();
    hole.loop = std::move(walk);
    // Half-edges the walk could not reach (inconsistent orientation) still belong here.
    for (int i : hs)
      if (!used[i]) {
        hole.simple = false;
        if (hole.touching_vertex < 0) hole.touching_vertex = half[i].first;
        used[i] = true;
      }
    std::vector<int> verts = hole.loop;
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    double d2 = 0;
    for (size_t a = 0; a < verts.size(); ++a)
      for (size_t b = a + 1; b < verts.size(); ++b)
        d2 = std::max(d2, (V.row(verts[a]) - V.row(verts[b])).squaredNorm());
    hole.diameter = std::sqrt(d2) / h;
    // Vector area ½ Σ p_k × p_{k+1} of the closed walk: the area of a planar loop, the
    // projected area of a bent one (a lower bound of any surface spanning it).
    Eigen::Vector3d va = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < hole.loop.size(); ++k) {
      const Eigen::Vector3d p = V.row(hole.loop[k]).transpose();
      const Eigen::Vector3d q = V.row(hole.loop[(k + 1) % hole.loop.size()]).transpose();
      va += 0.5 * p.cross(q);
    }
    hole.spanned_area = va.norm() / (h * h);
    holes.push_back(std::move(hole));
  }

  // Outer-boundary rule (see the header): per component, the widest loop when the area it
  // spans is at least a quarter of the component's surface area.
  std::vector<double> comp_area(static_cast<size_t>(ncomp), 0.0);
  const Eigen::VectorXd areas = face_areas(V, F);
  for (Eigen::Index f = 0; f < F.rows(); ++f) comp_area[comp(f)] += areas(f) / (h * h);
  std::vector<int> widest(static_cast<size_t>(ncomp), -1);
  for (size_t i = 0; i < holes.size(); ++i) {
    int& w = widest[holes[i].component];
    if (w < 0 || holes[i].diameter > holes[w].diameter ||
        (holes[i].diameter == holes[w].diameter && holes[i].edges > holes[w].edges))
      w = static_cast<int>(i);
  }
  for (int c = 0; c < ncomp; ++c) {
    const int w = widest[c];
    if (w >= 0) holes[w].outer_boundary = holes[w].spanned_area >= 0.25 * comp_area[c];
  }
  return holes;
}

}  // namespace msmesh
