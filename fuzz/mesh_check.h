// What a successfully read mesh must satisfy, checked by the fuzz targets (fuzz_reader.cpp)
// and by the regression tests of their inputs (FuzzRegressions.* in tests/test_read_mesh.cpp).
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <exception>
#include <string>

#include "msmesh/mesh.h"

namespace msmesh::fuzz {

/// "" when `m` is a valid mesh as read_mesh promises one, else what is wrong.
inline std::string mesh_problem(const Mesh& m) {
  const Eigen::Index nv = m.V.rows(), nf = m.F.rows();
  if (nv == 0 || nf == 0) return "no vertices or no faces";
  if (m.V.cols() != 3 || m.F.cols() != 3) return "V or F does not have 3 columns";
  if (!m.V.allFinite()) return "non-finite coordinate";
  for (Eigen::Index f = 0; f < nf; ++f) {
    for (int c = 0; c < 3; ++c)
      if (m.F(f, c) < 0 || m.F(f, c) >= nv) return "face index out of range";
    if (m.F(f, 0) == m.F(f, 1) || m.F(f, 1) == m.F(f, 2) || m.F(f, 0) == m.F(f, 2)) return "degenerate face";
  }
  if (m.vertex_colors.size() != 0) {
    if (m.vertex_colors.rows() != nv || (m.vertex_colors.cols() != 3 && m.vertex_colors.cols() != 4))
      return "vertex_colors is not #V by 3 or 4";
    if (!m.vertex_colors.allFinite() || m.vertex_colors.minCoeff() < 0 || m.vertex_colors.maxCoeff() > 1)
      return "vertex colour outside [0,1]";
  }
  if (m.uv.size() != 0) {
    if (m.uv.rows() != nv || m.uv.cols() != 2) return "uv is not #V by 2";
    if (!m.uv.allFinite()) return "non-finite texture coordinate";
  }
  if (m.vertex_normals.size() != 0) {
    if (m.vertex_normals.rows() != nv || m.vertex_normals.cols() != 3) return "vertex_normals is not #V by 3";
    if (!m.vertex_normals.allFinite()) return "non-finite vertex normal";
  }
  if (m.face_colors.size() != 0 &&
      (!m.face_colors.allFinite() || m.face_colors.minCoeff() < 0 || m.face_colors.maxCoeff() > 1))
    return "face colour outside [0,1]";
  if (m.texcoords.size() != 0 && !m.texcoords.allFinite()) return "non-finite per-corner texture coordinate";
  for (const VertexProperty& p : m.vertex_properties)
    if (p.values.size() != nv) return "vertex property " + p.name + " has not #V values";
  try {
    validate_attributes(m, "read mesh");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace msmesh::fuzz
