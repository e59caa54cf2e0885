// Mesh repair (docs/robustness.md): a direct implementation on index arrays, so that vertex
// and face order are kept and every change is counted.
#include "msmesh/repair.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <queue>
#include <sstream>
#include <unordered_map>

#include "msmesh/errors.h"
#include "msmesh/mesh_attributes.h"
#include "msmesh/parameters.h"
#include "msmesh/topology.h"

namespace msmesh {

const ParameterTable<RepairOptions>& repair_parameters() {
  using O = RepairOptions;
  using T = ParameterType;
  static const ParameterTable<O> t = {
      bind_parameter(ParameterInfo{"weld",
                                   "",
                                   "mean edge lengths",
                                   T::Real,
                                   {0, 1},
                                   "merge vertices closer than this (0: exact duplicates only)",
                                   "repair"},
                     &O::weld_tolerance),
      bind_parameter(ParameterInfo{"zero-area-tolerance",
                                   "",
                                   "squared mean edge lengths",
                                   T::Real,
                                   {0, 1},
                                   "faces of at most this area are degenerate",
                                   "repair"},
                     &O::zero_area_tolerance),
  };
  return t;
}

void RepairOptions::validate() const { check_parameters(repair_parameters(), *this); }

bool RepairReport::changed() const {
  return merged_vertices || degenerate_faces_removed || zero_area_faces_removed || duplicate_faces_removed ||
         flipped_faces || split_vertices || unreferenced_vertices_removed;
}

std::vector<std::string> RepairReport::actions() const {
  std::vector<std::string> a;
  auto add = [&](Eigen::Index n, const std::string& what) {
    if (n > 0) a.push_back(what + " " + std::to_string(n));
  };
  add(merged_vertices, "merged duplicate vertices:");
  add(degenerate_faces_removed, "removed faces repeating a vertex:");
  add(zero_area_faces_removed, "removed zero-area faces:");
  add(duplicate_faces_removed, "removed duplicate faces:");
  add(split_vertices, "split non-manifold vertices, copies added:");
  add(flipped_faces, "flipped faces to orient components consistently:");
  add(unreferenced_vertices_removed, "removed unreferenced vertices (vertices renumbered):");
  return a;
}

namespace {

using Edge = std::pair<int, int>;  // (min, max)
using Faces = std::vector<std::array<int, 3>>;

struct EdgeHash {
  std::size_t operator()(const Edge& e) const {
    return std::hash<std::uint64_t>()((std::uint64_t(std::uint32_t(e.first)) << 32) | std::uint32_t(e.second));
  }
};

Edge undirected(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

void check_input(const Mesh& m) {
  const Eigen::Index nv = m.V.rows();
  if (m.V.cols() != 3 && nv > 0)
    throw InvalidInput("repair: vertex array must be #V by 3, got " + std::to_string(nv) + " by " +
                       std::to_string(m.V.cols()));
  if (m.F.cols() != 3 && m.F.rows() > 0)
    throw InvalidInput("repair: face array must be #F by 3, got " + std::to_string(m.F.rows()) + " by " +
                       std::to_string(m.F.cols()));
  for (Eigen::Index i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(m.V(i, c)))
        throw InvalidInput("repair: vertex " + std::to_string(i) +
                           " has a non-finite coordinate (cannot be repaired; remove the vertex in the source)");
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) < 0 || m.F(f, k) >= nv)
        throw InvalidInput("repair: face " + std::to_string(f) + " refers to vertex " + std::to_string(m.F(f, k)) +
                           ", out of range [0, " + std::to_string(nv) + ")");
  validate_attributes(m, "repair");
}

double mean_face_edge_length(const Eigen::MatrixXd& V, const std::vector<std::array<int, 3>>& F) {
  double sum = 0;
  std::size_t n = 0;
  for (const auto& f : F)
    for (int k = 0; k < 3; ++k) {
      const double l = (V.row(f[k]) - V.row(f[(k + 1) % 3])).norm();
      if (l > 0) sum += l, ++n;
    }
  return n ? sum / double(n) : 1.0;
}

/// Representative (lowest index within `tol`) of each referenced vertex.
std::vector<int> weld(const Eigen::MatrixXd& V, const std::vector<bool>& referenced, double tol) {
  const int nv = static_cast<int>(V.rows());
  std::vector<int> rep(nv);
  std::iota(rep.begin(), rep.end(), 0);
  if (tol <= 0) {
    struct Key {
      double x, y, z;
      bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
    };
    struct KeyHash {
      std::size_t operator()(const Key& k) const {
        std::size_t h = 0;
        for (double d : {k.x, k.y, k.z}) {
          std::uint64_t b;
          std::memcpy(&b, &d, 8);
          h = h * 1000003u ^ std::hash<std::uint64_t>()(b);
        }
        return h;
      }
    };
    std::unordered_map<Key, int, KeyHash> seen;
    for (int i = 0; i < nv; ++i) {
      if (!referenced[i]) continue;
      const Key k{V(i, 0) + 0.0, V(i, 1) + 0.0, V(i, 2) + 0.0};  // + 0.0 turns -0 into +0
      auto [it, inserted] = seen.emplace(k, i);
      if (!inserted) rep[i] = it->second;
    }
    return rep;
  }
  // Grid of cell size tol; a vertex looks for a representative in the 27 cells around it.
  using Cell = std::array<long long, 3>;
  struct CellHash {
    std::size_t operator()(const Cell& c) const {
      return std::hash<long long>()(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
    }
  };
  std::unordered_map<Cell, std::vector<int>, CellHash> grid;
  for (int i = 0; i < nv; ++i) {
    if (!referenced[i]) continue;
    Cell c;
    for (int d = 0; d < 3; ++d) c[d] = static_cast<long long>(std::floor(V(i, d) / tol));
    int found = -1;
    for (long long dx = -1; dx <= 1 && found < 0; ++dx)
      for (long long dy = -1; dy <= 1 && found < 0; ++dy)
        for (long long dz = -1; dz <= 1 && found < 0; ++dz) {
          auto it = grid.find(Cell{c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (int j : it->second)
            if ((V.row(i) - V.row(j)).norm() <= tol && (found < 0 || j < found)) found = j;
        }
    if (found >= 0)
      rep[i] = found;
    else
      grid[c].push_back(i);
  }
  return rep;
}

/// Edge -> the faces on it, with +1 when the face walks it from min to max.
std::unordered_map<Edge, std::vector<std::pair<int, int>>, EdgeHash> edge_faces(
    const std::vector<std::array<int, 3>>& F) {
  std::unordered_map<Edge, std::vector<std::pair<int, int>>, EdgeHash> m;
  m.reserve(F.size() * 2);
  for (int f = 0; f < static_cast<int>(F.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F[f][k], b = F[f][(k + 1) % 3];
      m[undirected(a, b)].push_back({f, a < b ? 1 : -1});
    }
  return m;
}

// 1. Duplicate vertices: redirect faces to the first vertex of each cluster (within `tol`).
void merge_duplicate_vertices(const Eigen::MatrixXd& V, double tol, Faces& F, RepairReport& r) {
  const int nv0 = static_cast<int>(V.rows());
  std::vector<bool> referenced(nv0, false);
  for (const auto& f : F)
    for (int v : f) referenced[v] = true;
  const std::vector<int> rep = weld(V, referenced, tol);
  for (int i = 0; i < nv0; ++i) r.merged_vertices += rep[i] != i;
  for (auto& f : F)
    for (int& v : f) v = rep[v];
}

// 2. Degenerate, zero-area and duplicate faces (the first of equal faces is kept); `origin`
// follows the faces.
void remove_bad_faces(const Eigen::MatrixXd& V, const RepairOptions& o, double L, Faces& F, std::vector<int>& origin,
                      RepairReport& r) {
  Faces kept;
  std::vector<int> kept_origin;
  kept.reserve(F.size());
  std::map<std::array<int, 3>, int> seen;
  const double area_floor = o.zero_area_tolerance * L * L;
  for (std::size_t f = 0; f < F.size(); ++f) {
    const auto& t = F[f];
    if (o.remove_degenerate_faces) {
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
        ++r.degenerate_faces_removed;
        continue;
      }
      const Eigen::Vector3d a = V.row(t[0]), b = V.row(t[1]), c = V.row(t[2]);
      if (0.5 * (b - a).cross(c - a).norm() <= area_floor) {
        ++r.zero_area_faces_removed;
        continue;
      }
    }
    if (o.remove_duplicate_faces) {
      std::array<int, 3> key = t;
      std::sort(key.begin(), key.end());
      if (!seen.emplace(key, static_cast<int>(f)).second) {
        ++r.duplicate_faces_removed;
        continue;
      }
    }
    kept.push_back(t);
    kept_origin.push_back(origin[f]);
  }
  F = std::move(kept);
  origin = std::move(kept_origin);
}

// 3. Non-manifold vertices (and the ends of non-manifold edges): one vertex per fan of faces
//    joined through manifold edges. The fan with the lowest face keeps the vertex. Appends the
//    new vertices to `source_vertex` (the input row each vertex copies its attributes from).
void split_non_manifold_vertices(int nv0, Faces& F, std::vector<int>& source_vertex, RepairReport& r) {
  const Faces F0 = F;  // connectivity before any split
  const auto ef = edge_faces(F0);
  std::vector<std::vector<int>> vertex_faces(nv0);
  for (int f = 0; f < static_cast<int>(F.size()); ++f)
    for (int v : F[f]) vertex_faces[v].push_back(f);
  for (int v = 0; v < nv0; ++v) {
    const auto& faces = vertex_faces[v];
    if (faces.size() < 2) continue;
    // Union-find over the faces around v.
    std::unordered_map<int, int> slot;
    for (std::size_t i = 0; i < faces.size(); ++i) slot[faces[i]] = static_cast<int>(i);
    std::vector<int> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (int f : faces)
      for (int k = 0; k < 3; ++k) {
        const int w = F0[f][k];
        if (w == v) continue;
        const auto& on = ef.at(undirected(v, w));
        if (on.size() != 2) continue;
        const int a = find(slot[on[0].first]), b = find(slot[on[1].first]);
        parent[std::max(a, b)] = std::min(a, b);
      }
    std::map<int, int> group_vertex;  // root -> vertex index
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const int root = find(static_cast<int>(i));
      auto it = group_vertex.find(root);
      if (it == group_vertex.end()) {
        const int nv_now = static_cast<int>(source_vertex.size());
        const int target = group_vertex.empty() ? v : nv_now;
        if (target != v) {
          source_vertex.push_back(v);
          ++r.split_vertices;
        }
        it = group_vertex.emplace(root, target).first;
      }
      for (int& c : F[faces[i]])
        if (c == v) c = it->second;
    }
  }
}

// 4. Orientation: breadth-first over manifold edges from each component's first face; open
// components keep the orientation of most of their faces, closed orientable ones face outwards.
void orient_faces(const Eigen::MatrixXd& V, const std::vector<int>& source_vertex, Faces& F, std::vector<bool>& flipped,
                  RepairReport& r) {
  const auto ef = edge_faces(F);
  const int nf = static_cast<int>(F.size());
  std::vector<int> flip(nf, -1), comp(nf, -1);
  std::vector<bool> comp_closed, comp_bad;
  for (int seed = 0; seed < nf; ++seed) {
    if (comp[seed] >= 0) continue;
    const int c = static_cast<int>(comp_closed.size());
    comp_closed.push_back(true);
    comp_bad.push_back(false);
    std::queue<int> q;
    q.push(seed);
    comp[seed] = c;
    flip[seed] = 0;
    while (!q.empty()) {
      const int f = q.front();
      q.pop();
      for (int k = 0; k < 3; ++k) {
        const int a = F[f][k], b = F[f][(k + 1) % 3];
        const auto& on = ef.at(undirected(a, b));
        if (on.size() != 2) {
          comp_closed[c] = false;
          // Faces across a non-manifold edge still belong to the component (oriented by
          // their other edges where possible).
          for (const auto& [g, dir] : on)
            if (comp[g] < 0) {
              comp[g] = c;
              flip[g] = 0;
              q.push(g);
            }
          continue;
        }
        const auto& [f0, d0] = on[0];
        const auto& [f1, d1] = on[1];
        const int g = f0 == f ? f1 : f0;
        // Same walking direction -> one of the two must flip.
        const int want = flip[f] ^ (d0 == d1 ? 1 : 0);
        if (comp[g] < 0) {
          comp[g] = c;
          flip[g] = want;
          q.push(g);
        } else if (flip[g] != want) {
          comp_bad[c] = true;
        }
      }
    }
  }
  // Open components keep the orientation of the majority of their faces.
  std::vector<int> comp_faces(comp_closed.size(), 0), comp_flips(comp_closed.size(), 0);
  for (int f = 0; f < nf; ++f) ++comp_faces[comp[f]], comp_flips[comp[f]] += flip[f];
  for (int f = 0; f < nf; ++f)
    if (!comp_closed[comp[f]] && 2 * comp_flips[comp[f]] > comp_faces[comp[f]]) flip[f] ^= 1;
  for (int f = 0; f < nf; ++f)
    if (flip[f]) std::swap(F[f][1], F[f][2]);
  // Closed, orientable components face outwards: positive signed volume.
  std::vector<double> volume(comp_closed.size(), 0.0);
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d a = V.row(source_vertex[F[f][0]]), b = V.row(source_vertex[F[f][1]]),
                          cc = V.row(source_vertex[F[f][2]]);
    volume[comp[f]] += a.dot(b.cross(cc)) / 6.0;
  }
  for (int f = 0; f < nf; ++f) {
    const int c = comp[f];
    if (comp_closed[c] && !comp_bad[c] && volume[c] < 0) {
      std::swap(F[f][1], F[f][2]);
      flip[f] ^= 1;
    }
    r.flipped_faces += flip[f];
  }
  flipped.assign(static_cast<std::size_t>(nf), false);
  for (int f = 0; f < nf; ++f) flipped[static_cast<std::size_t>(f)] = flip[f] != 0;
  for (bool bad : comp_bad) r.non_orientable_components += bad;
}

// 5. Vertices: copies from splitting, then (optionally) only the referenced ones; writes V,
// the vertex attributes and F into `mesh` and the vertex map into r.
void store_result(Mesh& mesh, const std::vector<int>& source_vertex, bool remove_unreferenced, Faces& F,
                  const std::vector<int>& origin, const std::vector<bool>& flipped, RepairReport& r) {
  const int nv0 = static_cast<int>(mesh.V.rows());
  const int nv1 = static_cast<int>(source_vertex.size());
  std::vector<int> rows = source_vertex;  // output vertex i copies input row rows[i]
  std::vector<int> new_index(nv1);
  std::iota(new_index.begin(), new_index.end(), 0);
  if (remove_unreferenced) {
    std::vector<bool> used(nv1, false);
    for (const auto& f : F)
      for (int v : f) used[v] = true;
    std::vector<int> kept_rows;
    int next = 0;
    for (int i = 0; i < nv1; ++i) {
      if (used[i]) {
        new_index[i] = next++;
        kept_rows.push_back(rows[i]);
      } else {
        new_index[i] = -1;
        if (i < nv0) ++r.unreferenced_vertices_removed;
      }
    }
    rows = std::move(kept_rows);
    for (auto& f : F)
      for (int& v : f) v = new_index[v];
  }
  Mesh result;
  result.V.resize(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t i = 0; i < rows.size(); ++i) result.V.row(static_cast<Eigen::Index>(i)) = mesh.V.row(rows[i]);
  result.F.resize(static_cast<Eigen::Index>(F.size()), 3);
  for (std::size_t f = 0; f < F.size(); ++f) result.F.row(static_cast<Eigen::Index>(f)) << F[f][0], F[f][1], F[f][2];
  const Eigen::VectorXi vertex_origin =
      Eigen::Map<const Eigen::VectorXi>(rows.data(), static_cast<Eigen::Index>(rows.size()));
  const Eigen::VectorXi face_origin =
      Eigen::Map<const Eigen::VectorXi>(origin.data(), static_cast<Eigen::Index>(origin.size()));
  r.attribute_notes = carry_attributes(mesh, result, vertex_origin, face_origin, flipped);
  mesh = std::move(result);

  r.vertex_map.resize(nv0);
  for (int i = 0; i < nv0; ++i) r.vertex_map(i) = new_index[i];
}

}  // namespace

RepairReport repair_mesh(Mesh& mesh, const RepairOptions& o) {
  o.validate();
  check_input(mesh);
  RepairReport r;
  r.vertices_before = mesh.V.rows();
  r.faces_before = mesh.F.rows();
  const int nv0 = static_cast<int>(mesh.V.rows());

  Faces F(static_cast<std::size_t>(mesh.F.rows()));
  std::vector<int> origin(F.size());
  for (std::size_t f = 0; f < F.size(); ++f) {
    for (int k = 0; k < 3; ++k) F[f][k] = mesh.F(static_cast<Eigen::Index>(f), k);
    origin[f] = static_cast<int>(f);
  }
  const double L = mean_face_edge_length(mesh.V, F);

  if (o.merge_duplicate_vertices) merge_duplicate_vertices(mesh.V, o.weld_tolerance * L, F, r);
  remove_bad_faces(mesh.V, o, L, F, origin, r);
  std::vector<int> source_vertex(nv0);
  std::iota(source_vertex.begin(), source_vertex.end(), 0);
  if (o.split_non_manifold && !F.empty()) split_non_manifold_vertices(nv0, F, source_vertex, r);
  std::vector<bool> flipped;
  if (o.orient && !F.empty()) orient_faces(mesh.V, source_vertex, F, flipped, r);
  store_result(mesh, source_vertex, o.remove_unreferenced, F, origin, flipped, r);
  r.face_origin = Eigen::Map<const Eigen::VectorXi>(origin.data(), static_cast<Eigen::Index>(origin.size()));
  r.vertices_after = mesh.V.rows();
  r.faces_after = mesh.F.rows();

  const Topology topo = build_topology(mesh.F, mesh.V.rows());
  const TopologySummary s = summarize_topology(mesh.F, topo);
  r.components = s.components;
  r.unreferenced_vertices = s.unreferenced_vertices;
  r.non_manifold_edges = s.non_manifold_edges;
  r.non_manifold_vertices = s.non_manifold_vertices;
  return r;
}

}  // namespace msmesh
