// Internal: building blocks of the procedural shapes (shapes.cpp, fandisk.cpp, patch_mesher.cpp):
// a growing vertex/face list and the argument checks of the make_* functions.
#pragma once
#include <Eigen/Core>
#include <sstream>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/mesh.h"

namespace msmesh::detail {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

/// Throws InvalidInput(what) unless ok.
inline void require(bool ok, const std::string& what) {
  if (!ok) throw InvalidInput(what);
}

/// "function: param must be rule, got value".
inline std::string int_message(const char* function, const char* param, const char* rule, long long value) {
  std::ostringstream os;
  os << function << ": " << param << " must be " << rule << ", got " << value;
  return os.str();
}

/// Growing vertex and face lists.
struct MeshBuilder {
  std::vector<Vec3> V;
  std::vector<Eigen::Vector3i> F;

  int add_vertex(const Vec3& p) {
    V.push_back(p);
    return static_cast<int>(V.size()) - 1;
  }
  void add_triangle(int a, int b, int c) { F.emplace_back(a, b, c); }
  /// Quad a, b, c, d (counter-clockwise seen from outside), split along a–c.
  void add_quad(int a, int b, int c, int d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
  }
  Mesh to_mesh() const {
    Mesh m;
    m.V.resize(static_cast<Eigen::Index>(V.size()), 3);
    for (size_t i = 0; i < V.size(); ++i) m.V.row(static_cast<Eigen::Index>(i)) = V[i].transpose();
    m.F.resize(static_cast<Eigen::Index>(F.size()), 3);
    for (size_t i = 0; i < F.size(); ++i) m.F.row(static_cast<Eigen::Index>(i)) = F[i].transpose();
    return m;
  }
};

}  // namespace msmesh::detail
