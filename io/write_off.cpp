// OFF writer (COFF when the mesh has vertex colours).
#include <Eigen/Core>

#include "write_common.h"

namespace msmesh::io_detail {

void write_off(OutBuffer& o, const Mesh& m) {
  const bool colors = m.vertex_colors.size() > 0;
  // Coordinates read as float are written as float again (the same digits as the source).
  const bool f32 = m.position_type == ScalarType::Float32;
  auto coord = [&](double x) -> OutBuffer& { return f32 ? o.real32(static_cast<float>(x)) : o.real(x); };
  o.text(colors ? "COFF\n" : "OFF\n").integer(m.V.rows()).ch(' ').integer(m.F.rows()).text(" 0\n");
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    coord(m.V(i, 0)).ch(' ');
    coord(m.V(i, 1)).ch(' ');
    coord(m.V(i, 2));
    if (colors)
      o.ch(' ')
          .integer(color_byte(m.vertex_colors(i, 0)))
          .ch(' ')
          .integer(color_byte(m.vertex_colors(i, 1)))
          .ch(' ')
          .integer(color_byte(m.vertex_colors(i, 2)))
          .text(" 255");
    o.ch('\n');
  }
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    o.text("3 ").integer(m.F(f, 0)).ch(' ').integer(m.F(f, 1)).ch(' ').integer(m.F(f, 2)).ch('\n');
}

}  // namespace msmesh::io_detail
