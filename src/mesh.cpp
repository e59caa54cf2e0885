#include "msmesh/mesh.h"

#include <cmath>
#include <sstream>

#include "msmesh/errors.h"

namespace msmesh {

void validate_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what) {
  if (V.cols() != 3 && !(V.rows() == 0)) {
    std::ostringstream os;
    os << what << ": vertex array must be #V by 3, got " << V.rows() << " by " << V.cols();
    throw InvalidInput(os.str());
  }
  if (F.cols() != 3 && !(F.rows() == 0)) {
    std::ostringstream os;
    os << what << ": face array must be #F by 3, got " << F.rows() << " by " << F.cols();
    throw InvalidInput(os.str());
  }
  const bool all_finite = V.allFinite();  // (the search below only when there is something to find)
  for (Eigen::Index i = 0; i < V.rows() && !all_finite; ++i) {
    for (Eigen::Index c = 0; c < V.cols(); ++c) {
      if (!std::isfinite(V(i, c))) {
        std::ostringstream os;
        os << what << ": vertex " << i << " has a non-finite coordinate (" << V(i, c) << ")";
        throw InvalidInput(os.str());
      }
    }
  }
  // Squared lengths and areas of coordinates this far apart overflow to infinity, and the
  // errors computed from them to NaN: refused rather than processed into a NaN result.
  constexpr double kMaxSpan = 1e150;
  for (Eigen::Index c = 0; c < V.cols() && V.rows() > 0; ++c) {
    const double span = V.col(c).maxCoeff() - V.col(c).minCoeff();
    if (!(span <= kMaxSpan)) {
      std::ostringstream os;
      os << what << ": the vertex coordinates span " << span << " along axis "
         << "xyz"[c] << ", more than 1e150: their squared distances overflow; scale the mesh down";
      throw InvalidInput(os.str());
    }
  }
  const Eigen::Index n = V.rows();
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      if (F(f, k) < 0 || F(f, k) >= n) {
        std::ostringstream os;
        os << what << ": face " << f << " refers to vertex " << F(f, k) << ", out of range [0, " << n << ")";
        throw InvalidInput(os.str());
      }
    }
    if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 0) == F(f, 2)) {
      std::ostringstream os;
      os << what << ": face " << f << " repeats a vertex (" << F(f, 0) << ", " << F(f, 1) << ", " << F(f, 2) << ")";
      throw InvalidInput(os.str());
    }
  }
}

}  // namespace msmesh

namespace msmesh {

const char* scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::Int8:
      return "char";
    case ScalarType::UInt8:
      return "uchar";
    case ScalarType::Int16:
      return "short";
    case ScalarType::UInt16:
      return "ushort";
    case ScalarType::Int32:
      return "int";
    case ScalarType::UInt32:
      return "uint";
    case ScalarType::Float32:
      return "float";
    case ScalarType::Float64:
      return "double";
  }
  return "double";
}

void validate_attributes(const Mesh& m, const std::string& what) {
  const Eigen::Index nv = m.V.rows(), nf = m.F.rows();
  auto fail = [&what](const std::string& problem) { throw InvalidInput(what + ": " + problem); };
  auto shape = [&](const auto& M, Eigen::Index rows, std::initializer_list<Eigen::Index> cols, const char* name,
                   const char* expected) {
    if (M.size() == 0 && M.rows() == 0) return;
    bool ok = M.rows() == rows;
    bool col_ok = false;
    for (Eigen::Index c : cols) col_ok = col_ok || M.cols() == c;
    if (!ok || !col_ok)
      fail(std::string(name) + " must be empty or " + expected + ", got " + std::to_string(M.rows()) + " by " +
           std::to_string(M.cols()));
  };
  shape(m.vertex_colors, nv, {3, 4}, "vertex_colors", "#V by 3 or 4");
  shape(m.uv, nv, {2}, "uv", "#V by 2");
  shape(m.vertex_normals, nv, {3}, "vertex_normals", "#V by 3");
  shape(m.face_colors, nf, {3, 4}, "face_colors", "#F by 3 or 4");
  if (m.texcoords.size() > 0 && m.texcoords.cols() != 2) fail("texcoords must be #T by 2");
  shape(m.face_texcoords, nf, {3}, "face_texcoords", "#F by 3");
  for (Eigen::Index i = 0; i < m.face_texcoords.size(); ++i)
    if (m.face_texcoords(i) < -1 || m.face_texcoords(i) >= m.texcoords.rows())
      fail("face_texcoords refers to texture coordinate " + std::to_string(m.face_texcoords(i)) +
           ", out of range [-1, " + std::to_string(m.texcoords.rows()) + ")");
  auto index = [&](const Eigen::VectorXi& idx, const std::vector<std::string>& names, const char* name) {
    if (idx.size() == 0) return;
    if (idx.size() != nf) fail(std::string(name) + " must be empty or have #F entries");
    for (Eigen::Index f = 0; f < idx.size(); ++f)
      if (idx(f) < -1 || idx(f) >= static_cast<Eigen::Index>(names.size()))
        fail(std::string(name) + " of face " + std::to_string(f) + " is " + std::to_string(idx(f)) +
             ", out of range [-1, " + std::to_string(names.size()) + ")");
  };
  index(m.face_materials, m.material_names, "face_materials");
  index(m.face_groups, m.group_names, "face_groups");
  index(m.face_objects, m.object_names, "face_objects");
  for (const VertexProperty& p : m.vertex_properties) {
    if (p.name.empty()) fail("a vertex property has no name");
    if (p.values.size() != nv) fail("vertex property '" + p.name + "' must have #V values");
  }
}

}  // namespace msmesh
