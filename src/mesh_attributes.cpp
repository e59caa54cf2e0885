// carry_attributes (mesh_attributes.h): rows of the source's attribute arrays picked by the
// origin maps, and for new vertices and faces the values of the nearest source element found by
// a breadth-first search over the result's edges.
#include "msmesh/mesh_attributes.h"

#include <algorithm>
#include <cstdint>
#include <queue>
#include <unordered_map>
#include <utility>

#include "msmesh/errors.h"

namespace msmesh {
namespace {

/// For every element of a graph, the nearest element with a known origin (its own when it has
/// one), or −1 when none is reachable; `origin` has −1 for new elements.
Eigen::VectorXi nearest_known(const Eigen::VectorXi& origin, const std::vector<std::vector<int>>& adjacency) {
  const auto n = static_cast<int>(origin.size());
  Eigen::VectorXi from = origin;
  std::queue<int> q;
  for (int i = 0; i < n; ++i)
    if (from(i) >= 0) q.push(i);
  while (!q.empty()) {
    const int i = q.front();
    q.pop();
    for (int j : adjacency[static_cast<std::size_t>(i)])
      if (from(j) < 0) {
        from(j) = from(i);
        q.push(j);
      }
  }
  return from;
}

std::vector<std::vector<int>> vertex_adjacency(const Eigen::MatrixXi& F, Eigen::Index nv) {
  std::vector<std::vector<int>> adj(static_cast<std::size_t>(nv));
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      adj[static_cast<std::size_t>(a)].push_back(b);
      adj[static_cast<std::size_t>(b)].push_back(a);
    }
  return adj;
}

std::vector<std::vector<int>> face_adjacency(const Eigen::MatrixXi& F) {
  std::unordered_map<std::uint64_t, std::vector<int>> on_edge;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint32_t>(std::min(F(f, k), F(f, (k + 1) % 3)));
      const auto b = static_cast<std::uint32_t>(std::max(F(f, k), F(f, (k + 1) % 3)));
      on_edge[(std::uint64_t(a) << 32) | b].push_back(static_cast<int>(f));
    }
  std::vector<std::vector<int>> adj(static_cast<std::size_t>(F.rows()));
  for (const auto& [edge, faces] : on_edge)
    for (int f : faces)
      for (int g : faces)
        if (f != g) adj[static_cast<std::size_t>(f)].push_back(g);
  return adj;
}

Eigen::MatrixXd take_rows(const Eigen::MatrixXd& M, const Eigen::VectorXi& rows) {
  Eigen::MatrixXd out(rows.size(), M.cols());
  for (Eigen::Index i = 0; i < rows.size(); ++i) {
    if (rows(i) >= 0)
      out.row(i) = M.row(rows(i));
    else
      out.row(i) = M.colwise().mean();  // nothing reachable: the mean
  }
  return out;
}

Eigen::VectorXi take_indices(const Eigen::VectorXi& idx, const Eigen::VectorXi& rows) {
  Eigen::VectorXi out(rows.size());
  for (Eigen::Index i = 0; i < rows.size(); ++i) out(i) = rows(i) >= 0 ? idx(rows(i)) : -1;
  return out;
}

}  // namespace

bool has_attributes(const Mesh& m) {
  return m.vertex_colors.size() || m.uv.size() || m.vertex_normals.size() || m.face_colors.size() ||
         m.face_texcoords.size() || !m.material_libraries.empty() || m.face_materials.size() || m.face_groups.size() ||
         m.face_objects.size() || !m.vertex_properties.empty() || m.gltf_document;
}

bool corner_uv_to_vertex_uv(Mesh& m) {
  if (m.face_texcoords.rows() != m.F.rows() || m.F.rows() == 0) return false;
  Eigen::VectorXi of_vertex = Eigen::VectorXi::Constant(m.V.rows(), -1);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int t = m.face_texcoords(f, k);
      if (t < 0) return false;
      int& slot = of_vertex(m.F(f, k));
      if (slot < 0)
        slot = t;
      else if (slot != t && m.texcoords.row(slot) != m.texcoords.row(t))
        return false;
    }
  if (m.uv.rows() != m.V.rows() || m.uv.cols() != 2) m.uv.setZero(m.V.rows(), 2);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v)
    if (of_vertex(v) >= 0) m.uv.row(v) = m.texcoords.row(of_vertex(v));
  m.texcoords.resize(0, 2);
  m.face_texcoords.resize(0, 3);
  return true;
}

void copy_document_attributes(const Mesh& source, Mesh& result) {
  result.material_libraries = source.material_libraries;
  result.material_names = source.material_names;
  result.group_names = source.group_names;
  result.object_names = source.object_names;
  result.position_type = source.position_type;
  result.gltf_document = source.gltf_document;
}

std::vector<std::string> carry_attributes(const Mesh& s, Mesh& r, const Eigen::VectorXi& vertex_origin,
                                          const Eigen::VectorXi& face_origin, const std::vector<bool>& flipped) {
  const Eigen::Index nv = r.V.rows(), nf = r.F.rows();
  if (vertex_origin.size() != nv || face_origin.size() != nf)
    throw InvalidInput("carry_attributes: the origin maps must have #V and #F entries of the result");
  for (Eigen::Index i = 0; i < nv; ++i)
    if (vertex_origin(i) < -1 || vertex_origin(i) >= s.V.rows())
      throw InvalidInput("carry_attributes: vertex origin out of range");
  for (Eigen::Index f = 0; f < nf; ++f)
    if (face_origin(f) < -1 || face_origin(f) >= s.F.rows())
      throw InvalidInput("carry_attributes: face origin out of range");
  std::vector<std::string> notes;
  const Eigen::Index new_vertices = (vertex_origin.array() < 0).count();
  const Eigen::Index new_faces = (face_origin.array() < 0).count();

  copy_document_attributes(s, r);

  // Per-vertex attributes.
  const bool vertex_attributes =
      s.vertex_colors.size() || s.vertex_normals.size() || !s.vertex_properties.empty() || s.uv.size();
  const Eigen::VectorXi vfrom =
      new_vertices > 0 && vertex_attributes ? nearest_known(vertex_origin, vertex_adjacency(r.F, nv)) : vertex_origin;
  r.vertex_colors = s.vertex_colors.size() ? take_rows(s.vertex_colors, vfrom) : Eigen::MatrixXd();
  r.vertex_normals = s.vertex_normals.size() ? take_rows(s.vertex_normals, vfrom) : Eigen::MatrixXd();
  r.vertex_properties.clear();
  for (const VertexProperty& p : s.vertex_properties) {
    VertexProperty q{p.name, Eigen::VectorXd(nv), p.type};
    for (Eigen::Index i = 0; i < nv; ++i) q.values(i) = vfrom(i) >= 0 ? p.values(vfrom(i)) : p.values.mean();
    r.vertex_properties.push_back(std::move(q));
  }
  if (new_vertices > 0 && (s.vertex_colors.size() || !s.vertex_properties.empty()))
    notes.push_back(std::to_string(new_vertices) + " new vertices took their " +
                    (s.vertex_colors.size() ? "colours" : "vertex properties") +
                    (s.vertex_colors.size() && !s.vertex_properties.empty() ? " and vertex properties" : "") +
                    " from the nearest input vertex");

  // Per-face attributes.
  const bool face_attributes =
      s.face_colors.size() || s.face_materials.size() || s.face_groups.size() || s.face_objects.size();
  const Eigen::VectorXi ffrom =
      new_faces > 0 && face_attributes ? nearest_known(face_origin, face_adjacency(r.F)) : face_origin;
  r.face_colors = s.face_colors.size() ? take_rows(s.face_colors, ffrom) : Eigen::MatrixXd();
  r.face_materials = s.face_materials.size() ? take_indices(s.face_materials, ffrom) : Eigen::VectorXi();
  r.face_groups = s.face_groups.size() ? take_indices(s.face_groups, ffrom) : Eigen::VectorXi();
  r.face_objects = s.face_objects.size() ? take_indices(s.face_objects, ffrom) : Eigen::VectorXi();
  if (new_faces > 0 && face_attributes) {
    std::vector<std::string> what;
    if (s.face_colors.size()) what.emplace_back("colour");
    if (s.face_materials.size()) what.emplace_back("material");
    if (s.face_groups.size()) what.emplace_back("group");
    if (s.face_objects.size()) what.emplace_back("object");
    std::string list;
    for (std::size_t k = 0; k < what.size(); ++k)
      list += (k == 0 ? "" : k + 1 == what.size() ? " and " : ", ") + what[k];
    notes.push_back(std::to_string(new_faces) + " new faces took the " + list + " of a neighbouring face");
  }

  // Texture coordinates: per corner of the source faces.
  r.uv = s.uv.size() ? take_rows(s.uv, vfrom) : Eigen::MatrixXd();  // kept for unreferenced vertices
  r.texcoords.resize(0, 2);
  r.face_texcoords.resize(0, 3);
  const bool corner = s.face_texcoords.size() > 0, vertex = s.uv.size() > 0;
  if (corner || vertex) {
    r.texcoords = corner ? s.texcoords : s.uv;
    r.face_texcoords.resize(nf, 3);
    for (Eigen::Index f = 0; f < nf; ++f) {
      const int o = face_origin(f);
      const bool swap = static_cast<std::size_t>(f) < flipped.size() && flipped[static_cast<std::size_t>(f)];
      for (int k = 0; k < 3; ++k) {
        const int j = swap && k > 0 ? 3 - k : k;
        r.face_texcoords(f, k) = o < 0 ? -1 : corner ? s.face_texcoords(o, j) : s.F(o, j);
      }
    }
    // Per-vertex uv stays per-vertex when it can (the same vertices and faces kept).
    if (vertex && !corner_uv_to_vertex_uv(r)) {
      r.uv.resize(0, 2);
      if (new_faces == 0)
        notes.emplace_back("texture coordinates became per-corner (merged vertices had different ones)");
    }
    if (new_faces > 0) notes.push_back(std::to_string(new_faces) + " new faces have no texture coordinates");
  }
  return notes;
}

}  // namespace msmesh
