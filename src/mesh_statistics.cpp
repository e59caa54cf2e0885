#include "msmesh/mesh_statistics.h"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/topology.h"

namespace msmesh {

namespace {

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// Per face, whether it must be flipped so that its component is consistently oriented
/// (breadth-first over manifold edges from each component's first face). `orientable[c]`
/// becomes false where two paths disagree.
std::vector<bool> orientation_flips(const Topology& topo, const Eigen::VectorXi& comp, int count,
                                    std::vector<bool>& orientable) {
  const Eigen::Index nf = topo.num_faces();
  std::vector<bool> flip(static_cast<size_t>(nf), false), seen(static_cast<size_t>(nf), false);
  orientable.assign(static_cast<size_t>(count), true);
  std::vector<Eigen::Index> queue;
  for (Eigen::Index start = 0; start < nf; ++start) {
    if (seen[start]) continue;
    seen[start] = true;
    queue.assign(1, start);
    for (size_t q = 0; q < queue.size(); ++q) {
      const Eigen::Index f = queue[q];
      for (int k = 0; k < 3; ++k) {
        const int e = topo.face_edges(f, k);
        if (topo.edge_face_count(e) != 2) continue;
        const int g = topo.edge_faces(e, 0) == f ? topo.edge_faces(e, 1) : topo.edge_faces(e, 0);
        if (g < 0 || g == f) continue;
        int kg = 0;
        while (kg < 3 && topo.face_edges(g, kg) != e) ++kg;
        // Consistent when the two faces walk e in opposite directions after their flips.
        const int sf = topo.face_edge_signs(f, k) * (flip[f] ? -1 : 1);
        const int sg_file = topo.face_edge_signs(g, kg);
        const bool g_flip = sg_file == sf;  // g must be flipped to walk e as −sf
        if (!seen[g]) {
          seen[g] = true;
          flip[g] = g_flip;
          queue.push_back(g);
        } else if (flip[g] != g_flip) {
          orientable[comp(f)] = false;
        }
      }
    }
  }
  return flip;
}

}  // namespace

MeshStatistics mesh_statistics(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "mesh statistics");
  MeshStatistics s;
  const Eigen::Index nf = F.rows();
  const Topology topo = build_topology(F, V.rows());
  const TopologySummary summary = summarize_topology(F, topo);
  int count = 0;
  const Eigen::VectorXi comp = face_components(topo, &count);
  s.components = count;
  s.per_component.resize(static_cast<size_t>(count));
  std::vector<bool> orientable;
  const std::vector<bool> flip = orientation_flips(topo, comp, count, orientable);
  const Eigen::VectorXd areas = face_areas(V, F);

  // Non-manifold vertices: a vertex whose faces do not form one fan. Counted per component
  // through the vertices' fans: faces around a vertex connected across manifold edges.
  std::vector<bool> non_manifold_vertex(static_cast<size_t>(V.rows()), false);
  {
    std::vector<std::vector<int>> vertex_faces(static_cast<size_t>(V.rows()));
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) vertex_faces[F(f, k)].push_back(static_cast<int>(f));
    std::vector<int> mark(static_cast<size_t>(nf), -1);
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
      const auto& fan = vertex_faces[v];
      if (fan.size() < 2) continue;
      // Flood from the first face through edges that contain v and have two faces.
      std::vector<int> stack{fan[0]};
      mark[fan[0]] = static_cast<int>(v);
      size_t reached = 1;
      while (!stack.empty()) {
        const int f = stack.back();
        stack.pop_back();
        for (int k = 0; k < 3; ++k) {
          const int e = topo.face_edges(f, k);
          if (topo.edges(e, 0) != v && topo.edges(e, 1) != v) continue;
          if (topo.edge_face_count(e) != 2) continue;
          const int g = topo.edge_faces(e, 0) == f ? topo.edge_faces(e, 1) : topo.edge_faces(e, 0);
          if (g >= 0 && mark[g] != v) {
            mark[g] = static_cast<int>(v);
            ++reached;
            stack.push_back(g);
          }
        }
      }
      if (reached != fan.size()) non_manifold_vertex[v] = true;
    }
  }

  std::vector<int> vertex_stamp(static_cast<size_t>(V.rows()), -1);  // last component counting the vertex
  std::vector<bool> non_manifold_comp(static_cast<size_t>(count), false);
  std::vector<bool> inconsistent_comp(static_cast<size_t>(count), false);
  std::vector<bool> open_comp(static_cast<size_t>(count), false);
  std::vector<double> signed_volume(static_cast<size_t>(count), 0), flipped_volume(static_cast<size_t>(count), 0);
  for (Eigen::Index f = 0; f < nf; ++f) {
    ComponentStatistics& c = s.per_component[comp(f)];
    ++c.faces;
    c.area += areas(f);
    const Eigen::Vector3d p0 = V.row(F(f, 0)).transpose(), p1 = V.row(F(f, 1)).transpose(),
                          p2 = V.row(F(f, 2)).transpose();
    // About the component's first vertex would be better conditioned; the origin is what the
    // divergence theorem needs for a closed surface, and meshes are rarely far from it.
    const double vol = p0.dot(p1.cross(p2)) / 6.0;
    signed_volume[comp(f)] += vol;
    flipped_volume[comp(f)] += flip[f] ? -vol : vol;
    for (int k = 0; k < 3; ++k) {
      const int v = F(f, k);
      if (vertex_stamp[v] != comp(f)) {
        vertex_stamp[v] = comp(f);
        ++c.vertices;
        if (non_manifold_vertex[v]) non_manifold_comp[comp(f)] = true;
      }
    }
  }
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    const int c = comp(topo.edge_faces(e, 0));
    ++s.per_component[c].edges;
    const int n = topo.edge_face_count(e);
    if (n != 2) open_comp[c] = true;
    if (n > 2) non_manifold_comp[c] = true;
    if (n == 2 && !topo.edge_is_interior[e]) inconsistent_comp[c] = true;
  }
  // Boundary loops, by the component of a face on their first edge.
  std::unordered_map<std::uint64_t, int> boundary_edge_face;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
    if (topo.edge_face_count(e) == 1)
      boundary_edge_face[edge_key(topo.edges(e, 0), topo.edges(e, 1))] = topo.edge_faces(e, 0);
  for (const auto& loop : summary.boundary_loops) {
    const auto it = boundary_edge_face.find(edge_key(loop[0], loop[1]));
    if (it != boundary_edge_face.end()) ++s.per_component[comp(it->second)].boundary_loops;
  }

  std::vector<bool> used(static_cast<size_t>(V.rows()), false);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) used[F(f, k)] = true;
  Eigen::Index used_vertices = 0;
  for (bool u : used) used_vertices += u ? 1 : 0;

  bool every_genus = count > 0;
  Eigen::Index genus_sum = 0;
  for (int i = 0; i < count; ++i) {
    ComponentStatistics& c = s.per_component[i];
    c.closed = !open_comp[i];
    c.manifold = !non_manifold_comp[i];
    c.orientable = orientable[i] && c.manifold;
    c.consistently_oriented = c.orientable && !inconsistent_comp[i];
    c.euler_characteristic = c.vertices - c.edges + c.faces;
    if (c.closed && c.orientable) c.volume = c.consistently_oriented ? signed_volume[i] : std::abs(flipped_volume[i]);
    if (c.manifold && c.orientable) {
      const Eigen::Index twice = 2 - c.euler_characteristic - c.boundary_loops;
      c.genus = twice >= 0 && twice % 2 == 0 ? twice / 2 : -1;
    }
    if (c.genus < 0) every_genus = false;
    genus_sum += std::max<Eigen::Index>(c.genus, 0);
    if (c.closed) {
      ++s.closed_components;
      s.volume += c.volume;
    }
    s.area += c.area;
    s.boundary_loops += c.boundary_loops;
  }
  s.genus = every_genus ? genus_sum : -1;
  s.euler_characteristic = used_vertices - topo.num_edges() + nf;
  s.watertight = nf > 0 && summary.boundary_edges == 0 && summary.non_manifold_edges == 0 &&
                 summary.inconsistently_oriented_edges == 0;
  return s;
}

}  // namespace msmesh
