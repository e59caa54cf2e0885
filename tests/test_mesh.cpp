// mesh.h: the Mesh type's counts, and validate_mesh accepting what the operators handle and
// refusing, with a message naming the caller, the element and the value, what they cannot.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/mesh.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

/// The message of the InvalidInput that validate_mesh throws, or "" when it accepts.
std::string refusal(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what = "mesh") {
  try {
    validate_mesh(V, F, what);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Mesh, CountsAndEmptyAttributes) {
  const Mesh m = test::grid(3);
  EXPECT_EQ(m.num_vertices(), 16);
  EXPECT_EQ(m.num_faces(), 18);
  EXPECT_EQ(m.vertex_colors.size(), 0);
  EXPECT_EQ(m.uv.size(), 0);
  EXPECT_EQ(m.vertex_normals.size(), 0);
  const Mesh empty;
  EXPECT_EQ(empty.num_vertices(), 0);
  EXPECT_EQ(empty.num_faces(), 0);
}

TEST(Mesh, ValidateAcceptsWhatTheOperatorsHandle) {
  EXPECT_EQ(refusal(test::tetrahedron().V, test::tetrahedron().F), "");
  EXPECT_EQ(refusal(test::fin().V, test::fin().F), "") << "non-manifold edges are accepted";
  Mesh flat = test::tetrahedron();
  flat.V.row(3) = flat.V.row(0);  // zero-area faces, distinct indices
  EXPECT_EQ(refusal(flat.V, flat.F), "");
  EXPECT_EQ(refusal(Eigen::MatrixXd(0, 3), Eigen::MatrixXi(0, 3)), "") << "nothing to refuse";
  EXPECT_EQ(refusal(test::tetrahedron().V, Eigen::MatrixXi(0, 3)), "") << "vertices without faces";
}

TEST(Mesh, ValidateRefusalsNameTheElementAndValue) {
  const Mesh t = test::tetrahedron();
  EXPECT_EQ(refusal(Eigen::MatrixXd::Zero(4, 2), t.F, "in.obj"), "in.obj: vertex array must be #V by 3, got 4 by 2");
  EXPECT_EQ(refusal(t.V, Eigen::MatrixXi::Zero(2, 4)), "mesh: face array must be #F by 3, got 2 by 4");
  Eigen::MatrixXd V = t.V;
  V(1, 2) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(refusal(V, t.F), "mesh: vertex 1 has a non-finite coordinate (inf)");
  Eigen::MatrixXi F = t.F;
  F(2, 1) = -1;
  EXPECT_EQ(refusal(t.V, F), "mesh: face 2 refers to vertex -1, out of range [0, 4)");
  F = t.F;
  F(3, 0) = 4;
  EXPECT_EQ(refusal(t.V, F), "mesh: face 3 refers to vertex 4, out of range [0, 4)");
  F = t.F;
  F(1, 2) = F(1, 0);
  EXPECT_EQ(refusal(t.V, F), "mesh: face 1 repeats a vertex (0, 3, 0)");
}

TEST(Mesh, ValidateAttributesNamesTheBadOne) {
  Mesh m = test::grid(3);
  EXPECT_NO_THROW(validate_attributes(m, "m"));
  m.face_colors = Eigen::MatrixXd::Zero(m.F.rows(), 4);
  m.vertex_colors = Eigen::MatrixXd::Zero(m.V.rows(), 4);
  EXPECT_NO_THROW(validate_attributes(m, "m"));
  auto expect_refused = [](const Mesh& bad, const std::string& part) {
    try {
      validate_attributes(bad, "m");
      ADD_FAILURE() << "no InvalidInput for " << part;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  Mesh a = m;
  a.face_colors = Eigen::MatrixXd::Zero(m.F.rows() - 1, 3);
  expect_refused(a, "face_colors must be empty or #F by 3 or 4");
  Mesh b = m;
  b.texcoords = Eigen::MatrixXd::Zero(2, 2);
  b.face_texcoords = Eigen::MatrixXi::Constant(m.F.rows(), 3, 2);
  expect_refused(b, "out of range [-1, 2)");
  Mesh c = m;
  c.face_materials = Eigen::VectorXi::Zero(m.F.rows());
  expect_refused(c, "face_materials of face 0 is 0, out of range [-1, 0)");
  Mesh d = m;
  d.vertex_properties.push_back({"q", Eigen::VectorXd::Zero(2), ScalarType::Float32});
  expect_refused(d, "vertex property 'q' must have #V values");
  EXPECT_STREQ(scalar_type_name(ScalarType::UInt16), "ushort");
}
