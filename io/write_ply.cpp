// PLY writer, binary or ascii, and write_ply_face_colors. Coordinates are double, or float when
// the mesh was read from float coordinates; colours are uchar (alpha too); extra vertex
// properties keep their type; per-corner texture coordinates are MeshLab's face `texcoord` list.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>

#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"
#include "msmesh/write_mesh.h"
#include "write_common.h"

namespace msmesh {
namespace io_detail {
namespace {

template <class T>
T to_integer(double x) {
  if (std::isnan(x)) return 0;
  const double r = std::round(x);
  if (r <= static_cast<double>(std::numeric_limits<T>::lowest())) return std::numeric_limits<T>::lowest();
  if (r >= static_cast<double>(std::numeric_limits<T>::max())) return std::numeric_limits<T>::max();
  return static_cast<T>(r);
}

/// One integer value as T, binary or ascii (rounded and clamped to T's range).
template <class T>
void put_integer(OutBuffer& o, bool binary, double x) {
  const T v = to_integer<T>(x);
  if (binary)
    o.binary<T>(v);
  else
    o.integer(v);
}

/// One value as `type`, binary or ascii (integers rounded and clamped to the type's range).
void put(OutBuffer& o, bool binary, ScalarType type, double x) {
  switch (type) {
    case ScalarType::Int8:
      return put_integer<std::int8_t>(o, binary, x);
    case ScalarType::UInt8:
      return put_integer<std::uint8_t>(o, binary, x);
    case ScalarType::Int16:
      return put_integer<std::int16_t>(o, binary, x);
    case ScalarType::UInt16:
      return put_integer<std::uint16_t>(o, binary, x);
    case ScalarType::Int32:
      return put_integer<std::int32_t>(o, binary, x);
    case ScalarType::UInt32:
      return put_integer<std::uint32_t>(o, binary, x);
    case ScalarType::Float32:
      binary ? void(o.binary<float>(static_cast<float>(x))) : void(o.real32(static_cast<float>(x)));
      return;
    case ScalarType::Float64:
      binary ? void(o.binary<double>(x)) : void(o.real(x));
      return;
  }
}

}  // namespace

void write_ply(OutBuffer& o, const Mesh& m, bool binary, const Eigen::MatrixXd* face_colors) {
  const bool vcolors = m.vertex_colors.size() > 0, valpha = m.vertex_colors.cols() == 4;
  const bool uv = m.uv.size() > 0, normals = m.vertex_normals.size() > 0;
  const Eigen::MatrixXd* fc = face_colors ? face_colors : m.face_colors.size() > 0 ? &m.face_colors : nullptr;
  const bool falpha = fc && fc->cols() == 4, corner_uv = m.face_texcoords.size() > 0;
  // Float coordinates stay float (normals and uv with them); double otherwise (exact round trip).
  const ScalarType real = m.position_type == ScalarType::Float32 ? ScalarType::Float32 : ScalarType::Float64;
  const std::string rt = scalar_type_name(real);
  o.text("ply\nformat ").text(binary ? "binary_little_endian" : "ascii").text(" 1.0\ncomment written by msmesh\n");
  o.text("element vertex ").integer(m.V.rows()).ch('\n');
  for (const char* c : {"x", "y", "z"}) o.text("property ").text(rt).ch(' ').text(c).ch('\n');
  if (normals)
    for (const char* c : {"nx", "ny", "nz"}) o.text("property ").text(rt).ch(' ').text(c).ch('\n');
  if (vcolors) o.text("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  if (valpha) o.text("property uchar alpha\n");
  if (uv) o.text("property ").text(rt).text(" texture_u\nproperty ").text(rt).text(" texture_v\n");
  for (const VertexProperty& p : m.vertex_properties)
    o.text("property ").text(scalar_type_name(p.type)).ch(' ').text(p.name).ch('\n');
  o.text("element face ").integer(m.F.rows()).text("\nproperty list uchar int vertex_indices\n");
  if (fc) o.text("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  if (falpha) o.text("property uchar alpha\n");
  if (corner_uv) o.text("property list uchar ").text(rt).text(" texcoord\n");
  o.text("end_header\n");
  auto sep = [&] {
    if (!binary) o.ch(' ');
  };
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (c) sep();
      put(o, binary, real, m.V(i, c));
    }
    if (normals)
      for (int c = 0; c < 3; ++c) sep(), put(o, binary, real, m.vertex_normals(i, c));
    if (vcolors)
      for (int c = 0; c < m.vertex_colors.cols(); ++c) {
        sep();
        binary ? void(o.binary<std::uint8_t>(color_byte(m.vertex_colors(i, c))))
               : void(o.integer(color_byte(m.vertex_colors(i, c))));
      }
    if (uv)
      for (int c = 0; c < 2; ++c) sep(), put(o, binary, real, m.uv(i, c));
    for (const VertexProperty& p : m.vertex_properties) sep(), put(o, binary, p.type, p.values(i));
    if (!binary) o.ch('\n');
  }
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    if (binary) {
      o.binary<std::uint8_t>(3);
      for (int k = 0; k < 3; ++k) o.binary<std::int32_t>(m.F(f, k));
    } else {
      o.text("3 ").integer(m.F(f, 0)).ch(' ').integer(m.F(f, 1)).ch(' ').integer(m.F(f, 2));
    }
    if (fc)
      for (int c = 0; c < fc->cols(); ++c) {
        sep();
        binary ? void(o.binary<std::uint8_t>(color_byte((*fc)(f, c)))) : void(o.integer(color_byte((*fc)(f, c))));
      }
    if (corner_uv) {
      // A face with a corner without texture coordinates has none (an empty list).
      bool all = true;
      for (int k = 0; k < 3; ++k) all = all && m.face_texcoords(f, k) >= 0;
      sep();
      binary ? void(o.binary<std::uint8_t>(all ? 6 : 0)) : void(o.integer(all ? 6 : 0));
      if (all)
        for (int k = 0; k < 3; ++k)
          for (int c = 0; c < 2; ++c) sep(), put(o, binary, real, m.texcoords(m.face_texcoords(f, k), c));
    }
    if (!binary) o.ch('\n');
  }
}

}  // namespace io_detail

void write_ply_face_colors(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& face_colors, bool binary) {
  if (mesh_format_from_path(path) != "ply") throw IoError(path + ": face colours can only be written to a .ply file");
  if (face_colors.rows() != mesh.F.rows() || (face_colors.cols() != 3 && face_colors.cols() != 4))
    throw InvalidInput(path + ": face colours must be #F by 3 or 4 (" + std::to_string(mesh.F.rows()) + " by 3), got " +
                       std::to_string(face_colors.rows()) + " by " + std::to_string(face_colors.cols()));
  Mesh m = mesh;
  m.face_colors = face_colors;
  WriteOptions o;
  o.binary = binary;
  write_mesh(path, m, o);
}

}  // namespace msmesh
