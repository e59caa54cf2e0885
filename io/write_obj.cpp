// OBJ writer: vertices with optional "r g b" colours, vt and vn records, faces v/vt/vn.
#include <Eigen/Core>

#include "write_common.h"

namespace msmesh::io_detail {

void write_obj(OutBuffer& o, const Mesh& m) {
  const bool colors = m.vertex_colors.size() > 0, uv = m.uv.size() > 0;
  o.text("# written by msmesh\n");
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    o.text("v ").real(m.V(i, 0)).ch(' ').real(m.V(i, 1)).ch(' ').real(m.V(i, 2));
    // "v x y z r g b" is a widespread extension; readers that do not know it ignore the rest.
    if (colors)
      o.ch(' ').real(m.vertex_colors(i, 0)).ch(' ').real(m.vertex_colors(i, 1)).ch(' ').real(m.vertex_colors(i, 2));
    o.ch('\n');
  }
  if (uv)
    for (Eigen::Index i = 0; i < m.uv.rows(); ++i) o.text("vt ").real(m.uv(i, 0)).ch(' ').real(m.uv(i, 1)).ch('\n');
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
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    o.ch('f');
    for (int k = 0; k < 3; ++k) {
      o.ch(' ').integer(m.F(f, k) + 1LL);
      if (uv || normals) o.ch('/');
      if (uv) o.integer(m.F(f, k) + 1LL);
      if (normals) o.ch('/').integer(m.F(f, k) + 1LL);
    }
    o.ch('\n');
  }
}

}  // namespace msmesh::io_detail
