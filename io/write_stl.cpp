// STL writer, binary (float32) or ascii (full double precision), with unit face normals.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <string>

#include "msmesh/errors.h"
#include "write_common.h"

namespace msmesh::io_detail {
namespace {

Eigen::Vector3d unit_normal(const Mesh& m, Eigen::Index f) {
  const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double len = n.norm();
  return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

}  // namespace

void write_stl(OutBuffer& o, const Mesh& m, bool binary, const std::string& path) {
  if (binary) {
    if (m.F.rows() > static_cast<Eigen::Index>(std::numeric_limits<std::uint32_t>::max()))
      throw InvalidInput(path + ": too many faces for a binary STL (" + std::to_string(m.F.rows()) + ")");
    // The 80-byte header must not start with "solid", which would announce an ascii STL.
    std::string header = "binary STL written by msmesh";
    header.resize(80, ' ');
    o.text(header).binary<std::uint32_t>(static_cast<std::uint32_t>(m.F.rows()));
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
      const Eigen::Vector3d n = unit_normal(m, f);
      for (int c = 0; c < 3; ++c) o.binary<float>(static_cast<float>(n(c)));
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) o.binary<float>(static_cast<float>(m.V(m.F(f, k), c)));
      o.binary<std::uint16_t>(0);
    }
    return;
  }
  // Ascii STL: full double precision (readers that parse floats just round).
  o.text("solid msmesh\n");
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d n = unit_normal(m, f);
    o.text("facet normal ").real(n(0)).ch(' ').real(n(1)).ch(' ').real(n(2)).text("\n outer loop\n");
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index v = m.F(f, k);
      o.text("  vertex ").real(m.V(v, 0)).ch(' ').real(m.V(v, 1)).ch(' ').real(m.V(v, 2)).ch('\n');
    }
    o.text(" endloop\nendfacet\n");
  }
  o.text("endsolid msmesh\n");
}

}  // namespace msmesh::io_detail
