// OBJ writer: `mtllib` lines, vertices with optional "r g b" colours, vt and vn records, and the
// faces v/vt/vn with `o`, `g` and `usemtl` records where the face's object, group or material
// changes.
#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "write_common.h"

namespace msmesh::io_detail {

std::string library_path_from(const std::string& output, const std::string& library) {
  namespace fs = std::filesystem;
  const fs::path lib(library);
  // Relative to the current folder (as read_obj stores it) or absolute: written relative to
  // the output's folder, so that it names the same file.
  const fs::path out_dir = fs::path(output).parent_path();
  std::error_code ec;
  const fs::path base = fs::absolute(out_dir.empty() ? fs::path(".") : out_dir, ec);
  const fs::path target = fs::absolute(lib, ec);
  if (ec) return library;
  const fs::path rel = target.lexically_normal().lexically_relative(base.lexically_normal());
  return rel.empty() ? library : rel.string();
}

void write_obj(OutBuffer& o, const Mesh& m, const std::string& path) {
  const bool colors = m.vertex_colors.size() > 0, corner_uv = m.face_texcoords.size() > 0;
  const bool uv = !corner_uv && m.uv.size() > 0;
  o.text("# written by msmesh\n");
  // Coordinates read as float are written as float again (the same digits as the source).
  const bool f32 = m.position_type == ScalarType::Float32;
  const auto coord = [f32](std::string& s, double x) {
    if (f32)
      append_real(s, static_cast<float>(x));
    else
      append_real(s, x);
  };
  for (const std::string& lib : m.material_libraries) o.text("mtllib ").text(library_path_from(path, lib)).ch('\n');
  write_lines(o, m.V.rows(), [&](std::string& s, Eigen::Index i) {
    s += "v ";
    coord(s, m.V(i, 0));
    s += ' ';
    coord(s, m.V(i, 1));
    s += ' ';
    coord(s, m.V(i, 2));
    // "v x y z r g b" is a widespread extension; readers that do not know it ignore the rest.
    // (Alpha has no place in OBJ: unsupported_attributes names it.)
    if (colors)
      for (int c = 0; c < 3; ++c) {
        s += ' ';
        append_real(s, m.vertex_colors(i, c));
      }
    s += '\n';
  });
  if (uv)
    for (Eigen::Index i = 0; i < m.uv.rows(); ++i) o.text("vt ").real(m.uv(i, 0)).ch(' ').real(m.uv(i, 1)).ch('\n');
  if (corner_uv)
    for (Eigen::Index i = 0; i < m.texcoords.rows(); ++i)
      o.text("vt ").real(m.texcoords(i, 0)).ch(' ').real(m.texcoords(i, 1)).ch('\n');
  const bool normals = m.vertex_normals.size() > 0;
  if (normals)
    for (Eigen::Index i = 0; i < m.vertex_normals.rows(); ++i)
      o.text("vn ")
          .real(m.vertex_normals(i, 0))
          .ch(' ')
          .real(m.vertex_normals(i, 1))
          .ch(' ')
          .real(m.vertex_normals(i, 2))
          .ch('\n');
  if (!m.face_objects.size() && !m.face_groups.size() && !m.face_materials.size() && !corner_uv && !uv && !normals) {
    write_lines(o, m.F.rows(), [&](std::string& s, Eigen::Index f) {
      s += 'f';
      for (int k = 0; k < 3; ++k) {
        s += ' ';
        append_integer(s, m.F(f, k) + 1LL);
      }
      s += '\n';
    });
    return;
  }
  int object = -1, group = -1, material = -1;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    if (m.face_objects.size() && m.face_objects(f) >= 0 && m.face_objects(f) != object) {
      object = m.face_objects(f);
      o.text("o ").text(m.object_names[static_cast<std::size_t>(object)]).ch('\n');
    }
    if (m.face_groups.size() && m.face_groups(f) != group) {
      // A face without a group after grouped ones: "g" alone, the default group.
      group = m.face_groups(f);
      const std::string name = group >= 0 ? m.group_names[static_cast<std::size_t>(group)] : std::string();
      o.text(name.empty() ? "g" : "g ").text(name).ch('\n');
    }
    if (m.face_materials.size() && m.face_materials(f) >= 0 && m.face_materials(f) != material) {
      material = m.face_materials(f);
      o.text("usemtl ").text(m.material_names[static_cast<std::size_t>(material)]).ch('\n');
    }
    o.ch('f');
    for (int k = 0; k < 3; ++k) {
      const long long v = m.F(f, k) + 1LL;
      const long long t = corner_uv ? m.face_texcoords(f, k) + 1LL : uv ? v : 0;
      o.ch(' ').integer(v);
      if (t > 0 || normals) o.ch('/');
      if (t > 0) o.integer(t);
      if (normals) o.ch('/').integer(v);
    }
    o.ch('\n');
  }
}

}  // namespace msmesh::io_detail
