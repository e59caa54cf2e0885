// The hole puncher (punch_holes.h), for tests and benchmarks.
#include "msmesh/punch_holes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "format_number.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/topology.h"
#include "random.h"

namespace msmesh {

using detail::num;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Undirected vertex adjacency of F with edge lengths.
struct Adjacency {
  std::vector<std::vector<std::pair<int, double>>> nbr;
};

Adjacency vertex_adjacency(const Eigen::MatrixXd& V, const Topology& topo) {
  Adjacency a;
  a.nbr.resize(static_cast<size_t>(topo.num_vertices));
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    const int i = topo.edges(e, 0), j = topo.edges(e, 1);
    const double len = (V.row(i) - V.row(j)).norm();
    a.nbr[i].emplace_back(j, len);
    a.nbr[j].emplace_back(i, len);
  }
  return a;
}

// Geodesic (Dijkstra along edges) distances from the sources, up to `limit` (larger
// distances stay +inf).
std::vector<double> dijkstra(const Adjacency& adj, const std::vector<int>& sources, double limit) {
  std::vector<double> d(adj.nbr.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  for (int s : sources) {
    d[s] = 0;
    q.emplace(0.0, s);
  }
  while (!q.empty()) {
    const auto [du, u] = q.top();
    q.pop();
    if (du > d[u]) continue;
    for (const auto& [w, len] : adj.nbr[u]) {
      const double dw = du + len;
      if (dw < d[w] && dw <= limit) {
        d[w] = dw;
        q.emplace(dw, w);
      }
    }
  }
  return d;
}

}  // namespace

PunchResult punch_holes(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int count, double radius,
                        std::uint64_t seed, bool on_features) {
  validate_mesh(V, F, "punch holes");
  if (count < 0) throw InvalidInput("punch holes: count = " + std::to_string(count) + " must be >= 0");
  if (!(std::isfinite(radius) && radius > 0))
    throw InvalidInput("punch holes: radius = " + num(radius) + " must be > 0");
  const Eigen::Index nv = V.rows(), nf = F.rows();
  const Topology topo = build_topology(F, nv);
  const Adjacency adj = vertex_adjacency(V, topo);
  const double h = nf ? mean_edge_length(V, F) : 0;

  // Faces around each vertex.
  std::vector<std::vector<int>> vf(static_cast<size_t>(nv));
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) vf[F(f, k)].push_back(static_cast<int>(f));
  std::vector<bool> face_removed(static_cast<size_t>(nf), false), removed(static_cast<size_t>(nv), false);

  // Vertices near an existing boundary or non-manifold edge are off limits.
  std::vector<int> irregular;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
    if (!topo.edge_is_interior[e]) {
      irregular.push_back(topo.edges(e, 0));
      irregular.push_back(topo.edges(e, 1));
    }
  std::vector<bool> blocked(static_cast<size_t>(nv), false);
  {
    const std::vector<double> d = dijkstra(adj, irregular, 3 * h);
    for (Eigen::Index i = 0; i < nv; ++i) blocked[i] = std::isfinite(d[i]) || vf[i].empty();
  }

  std::vector<int> candidates;
  if (on_features) {
    const Eigen::VectorXd dihedral = dihedral_angles(V, F, topo);
    std::vector<bool> sharp(static_cast<size_t>(nv), false);
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
      if (dihedral(e) > kPi / 3) sharp[topo.edges(e, 0)] = sharp[topo.edges(e, 1)] = true;
    for (Eigen::Index i = 0; i < nv; ++i)
      if (sharp[i]) candidates.push_back(static_cast<int>(i));
  } else {
    for (Eigen::Index i = 0; i < nv; ++i)
      if (!vf[i].empty()) candidates.push_back(static_cast<int>(i));
  }
  detail::Random<std::mt19937_64> rng(seed);
  rng.shuffle(candidates);

  // Boundary degree of u once the faces touching `disk` are gone as well: the number of its
  // edges with exactly one remaining face; 0 remaining faces means u would be cut off.
  auto boundary_degree = [&](int u, const std::vector<bool>& in_disk, int* remaining) {
    std::unordered_map<int, int> edge_count;
    *remaining = 0;
    for (int f : vf[u]) {
      if (face_removed[f]) continue;
      bool gone = false;
      for (int k = 0; k < 3; ++k) gone = gone || in_disk[F(f, k)];
      if (gone) continue;
      ++*remaining;
      for (int k = 0; k < 3; ++k)
        if (F(f, k) != u) ++edge_count[F(f, k)];
    }
    int deg = 0;
    for (const auto& [w, c] : edge_count) {
      (void)w;
      if (c == 1) ++deg;
    }
    return deg;
  };

  PunchResult res;
  std::vector<bool> in_disk(static_cast<size_t>(nv), false);
  for (int c : candidates) {
    if (res.punched >= count) break;
    if (blocked[c] || removed[c]) continue;
    const std::vector<double> d = dijkstra(adj, {c}, radius * h);
    std::vector<int> disk;
    bool ok = true;
    for (Eigen::Index i = 0; i < nv && ok; ++i)
      if (std::isfinite(d[i])) {
        if (blocked[i]) ok = false;
        disk.push_back(static_cast<int>(i));
      }
    if (!ok) continue;
    for (int i : disk) in_disk[i] = true;
    // Grow the disk until every vertex on its rim has one gap in its fan (a simple loop).
    const size_t initial = disk.size();
    for (bool changed = true; changed && ok;) {
      changed = false;
      std::vector<int> rim;
      for (int i : disk)
        for (const auto& [w, len] : adj.nbr[i]) {
          (void)len;
          if (!in_disk[w]) rim.push_back(w);
        }
      std::sort(rim.begin(), rim.end());
      rim.erase(std::unique(rim.begin(), rim.end()), rim.end());
      for (int u : rim) {
        int remaining = 0;
        const int deg = boundary_degree(u, in_disk, &remaining);
        if (remaining == 0 || deg > 2) {
          if (blocked[u]) ok = false;
          in_disk[u] = true;
          disk.push_back(u);
          changed = true;
        }
      }
      if (disk.size() > 4 * initial + 16) ok = false;
    }
    if (!ok) {
      for (int i : disk) in_disk[i] = false;
      continue;
    }
    for (int i : disk) {
      removed[i] = true;
      for (int f : vf[i]) face_removed[f] = true;
    }
    for (int i : disk) in_disk[i] = false;
    // Keep later holes three mean edge lengths away from this one.
    const std::vector<double> near = dijkstra(adj, disk, 3 * h);
    for (Eigen::Index i = 0; i < nv; ++i)
      if (std::isfinite(near[i])) blocked[i] = true;
    res.centers.push_back(c);
    ++res.punched;
  }

  // Compact: keep remaining faces in order, drop unreferenced vertices.
  std::vector<bool> used(static_cast<size_t>(nv), false);
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!face_removed[f]) {
      ++kept;
      for (int k = 0; k < 3; ++k) used[F(f, k)] = true;
    }
  res.old_to_new = Eigen::VectorXi::Constant(nv, -1);
  std::vector<int> map;
  for (Eigen::Index i = 0; i < nv; ++i)
    if (used[i]) {
      res.old_to_new(i) = static_cast<int>(map.size());
      map.push_back(static_cast<int>(i));
    }
  res.vertex_map = Eigen::Map<const Eigen::VectorXi>(map.data(), static_cast<Eigen::Index>(map.size()));
  res.V.resize(static_cast<Eigen::Index>(map.size()), 3);
  for (size_t i = 0; i < map.size(); ++i) res.V.row(static_cast<Eigen::Index>(i)) = V.row(map[i]);
  res.F.resize(kept, 3);
  res.face_map.resize(kept);
  Eigen::Index r = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!face_removed[f]) {
      for (int k = 0; k < 3; ++k) res.F(r, k) = res.old_to_new(F(f, k));
      res.face_map(r) = static_cast<int>(f);
      ++r;
    }
  return res;
}

}  // namespace msmesh
