// PLY writer, binary or ascii, with double coordinates, and write_ply_face_colors.
#include <Eigen/Core>
#include <cstdint>
#include <ostream>
#include <string>

#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"
#include "msmesh/write_mesh.h"
#include "write_common.h"

namespace msmesh {
namespace io_detail {

/// PLY with double coordinates (exact round trip), optional vertex normals, colours and uv, and
/// optional per-face colours.
void write_ply(OutBuffer& o, const Mesh& m, bool binary, const Eigen::MatrixXd* face_colors) {
  const bool vcolors = m.vertex_colors.size() > 0, uv = m.uv.size() > 0, normals = m.vertex_normals.size() > 0;
  o.text("ply\nformat ").text(binary ? "binary_little_endian" : "ascii").text(" 1.0\ncomment written by msmesh\n");
  o.text("element vertex ").integer(m.V.rows()).text("\nproperty double x\nproperty double y\nproperty double z\n");
  if (normals) o.text("property double nx\nproperty double ny\nproperty double nz\n");
  if (vcolors) o.text("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  if (uv) o.text("property double texture_u\nproperty double texture_v\n");
  o.text("element face ").integer(m.F.rows()).text("\nproperty list uchar int vertex_indices\n");
  if (face_colors) o.text("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  o.text("end_header\n");
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    if (binary) {
      for (int c = 0; c < 3; ++c) o.binary<double>(m.V(i, c));
      if (normals)
        for (int c = 0; c < 3; ++c) o.binary<double>(m.vertex_normals(i, c));
      if (vcolors)
        for (int c = 0; c < 3; ++c) o.binary<std::uint8_t>(color_byte(m.vertex_colors(i, c)));
      if (uv)
        for (int c = 0; c < 2; ++c) o.binary<double>(m.uv(i, c));
    } else {
      o.real(m.V(i, 0)).ch(' ').real(m.V(i, 1)).ch(' ').real(m.V(i, 2));
      if (normals)
        for (int c = 0; c < 3; ++c) o.ch(' ').real(m.vertex_normals(i, c));
      if (vcolors)
        for (int c = 0; c < 3; ++c) o.ch(' ').integer(color_byte(m.vertex_colors(i, c)));
      if (uv) o.ch(' ').real(m.uv(i, 0)).ch(' ').real(m.uv(i, 1));
      o.ch('\n');
    }
  }
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    if (binary) {
      o.binary<std::uint8_t>(3);
      for (int k = 0; k < 3; ++k) o.binary<std::int32_t>(m.F(f, k));
      if (face_colors)
        for (int c = 0; c < 3; ++c) o.binary<std::uint8_t>(color_byte((*face_colors)(f, c)));
    } else {
      o.text("3 ").integer(m.F(f, 0)).ch(' ').integer(m.F(f, 1)).ch(' ').integer(m.F(f, 2));
      if (face_colors)
        for (int c = 0; c < 3; ++c) o.ch(' ').integer(color_byte((*face_colors)(f, c)));
      o.ch('\n');
    }
  }
}

}  // namespace io_detail

void write_ply_face_colors(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& face_colors, bool binary) {
  if (mesh_format_from_path(path) != "ply") throw IoError(path + ": face colours can only be written to a .ply file");
  io_detail::check_for_writing(path, mesh);
  if (face_colors.rows() != mesh.F.rows() || face_colors.cols() != 3)
    throw InvalidInput(path + ": face colours must be #F by 3 (" + std::to_string(mesh.F.rows()) + " by 3), got " +
                       std::to_string(face_colors.rows()) + " by " + std::to_string(face_colors.cols()));
  write_file_atomically(path, [&](std::ostream& out) {
    io_detail::OutBuffer o(out);
    io_detail::write_ply(o, mesh, binary, &face_colors);
    o.finish();
  });
}

}  // namespace msmesh
