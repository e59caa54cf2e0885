#include "msmesh/topology.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>

#include "msmesh/errors.h"
#include "parallel.h"
#include "union_find.h"

namespace msmesh {

Topology build_topology(const Eigen::MatrixXi& F, Eigen::Index num_vertices) {
  Topology t;
  t.num_vertices = num_vertices;
  const Eigen::Index nf = F.rows();
  // Half-edges (f, k): from F(f,k+1) to F(f,k+2), keyed by (min, max); sorting groups them.
  struct HalfEdge {
    int lo, hi, face, corner;
  };
  // Counting sort on lo (linear time), then the few half-edges of each vertex by (hi, face,
  // corner): the same order as a full sort on (lo, hi, face, corner), so the same numbering.
  Eigen::Index max_vertex = num_vertices;
  if (F.cols() != 3 && nf > 0) throw InvalidInput("topology: faces must be #F by 3");
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      if (F(f, k) < 0)
        throw InvalidInput("topology: face " + std::to_string(f) + " has a negative vertex index " +
                           std::to_string(F(f, k)));
      max_vertex = std::max<Eigen::Index>(max_vertex, F(f, k) + 1);
    }
  std::vector<int> start(static_cast<size_t>(max_vertex) + 1, 0);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++start[static_cast<size_t>(std::min(F(f, (k + 1) % 3), F(f, (k + 2) % 3))) + 1];
  for (size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  // Not value-initialised: its pages are first touched in parallel, then filled (a million
  // faces: 63 MB, whose first touch on one thread cost as much as the rest of the sort).
  const size_t nh = static_cast<size_t>(3 * nf);
  std::unique_ptr<HalfEdge[]> he_storage(new HalfEdge[nh]);
  HalfEdge* const he = he_storage.get();
  detail::parallel_for_blocks(static_cast<Eigen::Index>(nh),
                              [&](Eigen::Index i0, Eigen::Index i1) { std::fill(he + i0, he + i1, HalfEdge{}); });
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Eigen::Index f = 0; f < nf; ++f) {
      for (int k = 0; k < 3; ++k) {
        const int a = F(f, (k + 1) % 3), b = F(f, (k + 2) % 3);
        const int lo = std::min(a, b);
        he[static_cast<size_t>(fill[static_cast<size_t>(lo)]++)] = {lo, std::max(a, b), static_cast<int>(f), k};
      }
    }
  }
  const auto less = [](const HalfEdge& x, const HalfEdge& y) {
    if (x.hi != y.hi) return x.hi < y.hi;
    if (x.face != y.face) return x.face < y.face;
    return x.corner < y.corner;
  };
  // Each vertex's bucket on its own (in parallel): sorted, its edges counted; then numbered
  // from the counts before it, so the numbering is the serial one.
  const Eigen::Index nb = max_vertex;
  std::vector<int> bucket_edges(static_cast<size_t>(nb) + 1, 0);
  detail::parallel_for(
      nb,
      [&](Eigen::Index v) {
        HalfEdge* const b = he + start[static_cast<size_t>(v)];
        HalfEdge* const e = he + start[static_cast<size_t>(v) + 1];
        // Nothing to sort; also keeps `b + 1` inside the array (UBSan: offset applied to the
        // null data pointer of an empty array when F has no faces).
        if (e - b < 2) {
          bucket_edges[static_cast<size_t>(v) + 1] = static_cast<int>(e - b);
          return;
        }
        if (e - b < 32) {  // insertion sort: buckets hold a vertex's few edges
          for (auto i = b + 1; i < e; ++i)
            for (auto j = i; j > b && less(*j, *(j - 1)); --j) std::iter_swap(j, j - 1);
        } else {
          std::sort(b, e, less);
        }
        int distinct = 1;
        for (auto i = b + 1; i < e; ++i) distinct += i->hi != (i - 1)->hi;
        bucket_edges[static_cast<size_t>(v) + 1] = distinct;
      },
      4);
  for (size_t v = 0; v < static_cast<size_t>(nb); ++v) bucket_edges[v + 1] += bucket_edges[v];
  const Eigen::Index ne = bucket_edges.back();

  t.edges.resize(ne, 2);
  t.edge_faces.setConstant(ne, 2, -1);
  t.edge_face_count.setZero(ne);
  t.edge_is_interior.assign(static_cast<size_t>(ne), false);
  t.face_edges.resize(nf, 3);
  t.face_edge_signs.resize(nf, 3);

  // A bucket holds every half-edge of its edges (they share the lower vertex).
  detail::parallel_for(
      nb,
      [&](Eigen::Index v) {
        Eigen::Index e = bucket_edges[static_cast<size_t>(v)] - 1;
        for (int i = start[static_cast<size_t>(v)]; i < start[static_cast<size_t>(v) + 1]; ++i) {
          const HalfEdge& h = he[static_cast<size_t>(i)];
          if (i == start[static_cast<size_t>(v)] || h.hi != he[static_cast<size_t>(i) - 1].hi) {
            ++e;
            t.edges(e, 0) = h.lo;
            t.edges(e, 1) = h.hi;
          }
          const int f = h.face, k = h.corner;
          const int from = F(f, (k + 1) % 3);
          const int sign = (from == h.lo) ? 1 : -1;
          t.face_edges(f, k) = static_cast<int>(e);
          t.face_edge_signs(f, k) = sign;
          const int c = t.edge_face_count(e)++;
          if (c < 2) t.edge_faces(e, c) = f;
        }
      },
      4);
  // (std::vector<bool> packs its bits: set from the bytes after the parallel loop.)
  std::vector<char> interior(static_cast<size_t>(ne), 0);
  detail::parallel_for(ne, [&](Eigen::Index ei) {
    if (t.edge_face_count(ei) != 2) return;
    const int f0 = t.edge_faces(ei, 0), f1 = t.edge_faces(ei, 1);
    auto sign_in = [&](int f) {
      for (int k = 0; k < 3; ++k)
        if (t.face_edges(f, k) == ei) return t.face_edge_signs(f, k);
      return 0;
    };
    const int s0 = sign_in(f0), s1 = sign_in(f1);
    if (s0 != s1) {
      interior[static_cast<size_t>(ei)] = 1;
      if (s0 < 0) std::swap(t.edge_faces(ei, 0), t.edge_faces(ei, 1));
    }
  });
  for (Eigen::Index ei = 0; ei < ne; ++ei)
    t.edge_is_interior[static_cast<size_t>(ei)] = interior[static_cast<size_t>(ei)];
  return t;
}

using detail::UnionFind;

Eigen::VectorXi face_components(const Topology& topo, int* count) {
  const Eigen::Index nf = topo.num_faces();
  UnionFind uf(static_cast<size_t>(nf));
  // Faces sharing any edge (also non-manifold ones) belong together; collect all faces per edge.
  std::vector<int> first(static_cast<size_t>(topo.num_edges()), -1);
  for (Eigen::Index f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int e = topo.face_edges(f, k);
      if (first[e] < 0)
        first[e] = static_cast<int>(f);
      else
        uf.unite(static_cast<int>(f), first[e]);
    }
  }
  Eigen::VectorXi label(nf);
  std::unordered_map<int, int> ids;
  for (Eigen::Index f = 0; f < nf; ++f) {
    const int r = uf.find(static_cast<int>(f));
    auto it = ids.emplace(r, static_cast<int>(ids.size())).first;
    label(f) = it->second;
  }
  if (count) *count = static_cast<int>(ids.size());
  return label;
}

TopologySummary summarize_topology(const Eigen::MatrixXi& F, const Topology& topo) {
  TopologySummary s;
  const Eigen::Index nv = topo.num_vertices, ne = topo.num_edges(), nf = topo.num_faces();
  std::vector<int> boundary_degree(static_cast<size_t>(nv), 0);
  std::vector<bool> vertex_on_nm_edge(static_cast<size_t>(nv), false);
  for (Eigen::Index e = 0; e < ne; ++e) {
    const int c = topo.edge_face_count(e);
    if (c == 1) {
      ++s.boundary_edges;
      ++boundary_degree[topo.edges(e, 0)];
      ++boundary_degree[topo.edges(e, 1)];
    } else if (c > 2) {
      ++s.non_manifold_edges;
      vertex_on_nm_edge[topo.edges(e, 0)] = vertex_on_nm_edge[topo.edges(e, 1)] = true;
    } else if (!topo.edge_is_interior[e]) {
      ++s.inconsistently_oriented_edges;
    }
  }
  // Non-manifold vertices: the faces around a vertex, linked through shared manifold edges at
  // that vertex, must form one fan.
  std::vector<int> valence(static_cast<size_t>(nv), 0);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++valence[F(f, k)];
  for (Eigen::Index v = 0; v < nv; ++v)
    if (valence[v] == 0) ++s.unreferenced_vertices;
  {
    // Count fans per vertex with a union-find over (vertex, face) corners.
    std::vector<int> corner_start(static_cast<size_t>(nv) + 1, 0);
    for (Eigen::Index v = 0; v < nv; ++v) corner_start[v + 1] = corner_start[v] + valence[v];
    std::vector<int> fill(corner_start.begin(), corner_start.end() - 1);
    std::vector<int> corner_face(static_cast<size_t>(3 * nf));
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) corner_face[fill[F(f, k)]++] = static_cast<int>(f);
    UnionFind uf(corner_face.size());
    auto corner_of = [&](int v, int f) {
      for (int i = corner_start[v]; i < corner_start[v + 1]; ++i)
        if (corner_face[i] == f) return i;
      return -1;
    };
    for (Eigen::Index e = 0; e < ne; ++e) {
      if (topo.edge_face_count(e) != 2) continue;
      const int f0 = topo.edge_faces(e, 0), f1 = topo.edge_faces(e, 1);
      for (int end = 0; end < 2; ++end) {
        const int v = topo.edges(e, end);
        uf.unite(corner_of(v, f0), corner_of(v, f1));
      }
    }
    for (Eigen::Index v = 0; v < nv; ++v) {
      int fans = 0;
      for (int i = corner_start[v]; i < corner_start[v + 1]; ++i)
        if (uf.find(i) == i) ++fans;
      if (fans > 1 || vertex_on_nm_edge[v] || boundary_degree[v] > 2) ++s.non_manifold_vertices;
    }
  }
  int comps = 0;
  face_components(topo, &comps);
  s.components = comps;

  // Boundary loops: follow boundary edges in the direction their face walks them reversed
  // (the hole's boundary), only through vertices with exactly two boundary edges.
  std::vector<int> next(static_cast<size_t>(nv), -1);
  for (Eigen::Index e = 0; e < ne; ++e) {
    if (topo.edge_face_count(e) != 1) continue;
    const int f = topo.edge_faces(e, 0);
    int k = 0;
    while (topo.face_edges(f, k) != e) ++k;
    const int from = F(f, (k + 1) % 3), to = F(f, (k + 2) % 3);
    // The face walks from→to; the hole boundary loop walks to→from.
    if (boundary_degree[to] == 2 && boundary_degree[from] == 2) next[to] = from;
  }
  std::vector<bool> seen(static_cast<size_t>(nv), false);
  for (Eigen::Index v0 = 0; v0 < nv; ++v0) {
    if (next[v0] < 0 || seen[v0]) continue;
    std::vector<int> loop;
    int v = static_cast<int>(v0);
    bool closed = false;
    while (v >= 0 && !seen[v]) {
      seen[v] = true;
      loop.push_back(v);
      v = next[v];
      if (v == v0) {
        closed = true;
        break;
      }
    }
    if (closed && loop.size() >= 3) s.boundary_loops.push_back(std::move(loop));
  }
  return s;
}

}  // namespace msmesh
