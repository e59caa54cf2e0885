// Carrying attributes to a mesh made from another (msmesh/mesh_attributes.h): rows follow the
// origin maps, new vertices and faces take their nearest source's values, texture coordinates
// follow corners (flipped faces too), per-corner uv collapses to per-vertex when it can.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/mesh_attributes.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

/// Two triangles (0,1,2), (0,2,3) of a unit square, with every kind of attribute.
Mesh square() {
  Mesh m;
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 2, 3;
  m.vertex_colors.resize(4, 4);
  m.vertex_colors << 1, 0, 0, 1, 0, 1, 0, 0.5, 0, 0, 1, 1, 1, 1, 0, 0.25;
  m.face_colors.resize(2, 3);
  m.face_colors << 0.1, 0.2, 0.3, 0.4, 0.5, 0.6;
  m.texcoords.resize(6, 2);
  m.texcoords << 0, 0, 1, 0, 1, 1, 0.5, 0, 0.5, 1, 0, 1;
  m.face_texcoords.resize(2, 3);
  m.face_texcoords << 0, 1, 2, 3, 4, 5;
  m.material_names = {"red", "blue"};
  m.face_materials.resize(2);
  m.face_materials << 1, 0;
  m.group_names = {"g"};
  m.face_groups = Eigen::VectorXi::Zero(2);
  m.vertex_properties.push_back({"quality", Eigen::Vector4d(1, 2, 3, 4), ScalarType::UInt8});
  m.material_libraries = {"a.mtl"};
  m.position_type = ScalarType::Float32;
  return m;
}

}  // namespace

TEST(CarryAttributes, NewVerticesAndFacesTakeTheirNeighboursValues) {
  const Mesh s = square();
  // A fan of two new faces around a new vertex 4 outside edge (1,2).
  Mesh r;
  r.V.resize(5, 3);
  r.V << s.V, Eigen::RowVector3d(2, 0.5, 0);
  r.F.resize(4, 3);
  r.F << s.F, Eigen::RowVector3i(1, 4, 2), Eigen::RowVector3i(2, 4, 3);
  Eigen::VectorXi vo(5), fo(4);
  vo << 0, 1, 2, 3, -1;
  fo << 0, 1, -1, -1;
  const std::vector<std::string> notes = carry_attributes(s, r, vo, fo);
  ASSERT_NO_THROW(validate_attributes(r, "result"));
  // The new vertex is one edge from vertices 1 and 2: it takes one of theirs.
  EXPECT_TRUE(r.vertex_colors.row(4) == s.vertex_colors.row(1) || r.vertex_colors.row(4) == s.vertex_colors.row(2));
  EXPECT_TRUE(r.vertex_properties[0].values(4) == 2 || r.vertex_properties[0].values(4) == 3);
  EXPECT_EQ(r.vertex_properties[0].type, ScalarType::UInt8);
  // New face 2 shares edge (1,2) with face 0: its material and colour.
  EXPECT_EQ(r.face_materials(2), 1);
  EXPECT_EQ(r.face_colors.row(2), s.face_colors.row(0));
  EXPECT_EQ(r.face_groups(3), 0);
  // Old faces keep their corners' texture coordinates, new ones have none.
  EXPECT_EQ(r.face_texcoords.topRows(2), s.face_texcoords);
  EXPECT_EQ(r.face_texcoords.row(2), Eigen::RowVector3i(-1, -1, -1));
  EXPECT_EQ(r.texcoords, s.texcoords);
  EXPECT_EQ(r.material_names, s.material_names);
  EXPECT_EQ(r.material_libraries, s.material_libraries);
  EXPECT_EQ(r.position_type, ScalarType::Float32);
  std::string all;
  for (const std::string& n : notes) all += n + "\n";
  EXPECT_NE(all.find("2 new faces have no texture coordinates"), std::string::npos) << all;
  EXPECT_NE(all.find("2 new faces took the colour, material and group of a neighbouring face"), std::string::npos)
      << all;
  EXPECT_NE(all.find("1 new vertices took their colours and vertex properties"), std::string::npos) << all;
}

TEST(CarryAttributes, FacesFollowTheirOriginAndFlippedCornersSwap) {
  const Mesh s = square();
  Mesh r;
  r.V = s.V;
  r.F.resize(2, 3);
  r.F << 0, 3, 2, 0, 2, 1;  // faces swapped in order, the second flipped (0,2,1) of (0,1,2)
  Eigen::VectorXi vo(4), fo(2);
  vo << 0, 1, 2, 3;
  fo << 1, 0;
  const std::vector<bool> flipped = {true, true};
  // Face 0 is source face 1 (0,2,3) flipped: corners (0,3,2).
  EXPECT_TRUE(carry_attributes(s, r, vo, fo, flipped).empty());
  EXPECT_EQ(r.face_texcoords.row(0), Eigen::RowVector3i(3, 5, 4));
  EXPECT_EQ(r.face_texcoords.row(1), Eigen::RowVector3i(0, 2, 1));
  EXPECT_EQ(r.face_materials(0), 0);
  EXPECT_EQ(r.face_colors.row(0), s.face_colors.row(1));
}

TEST(CarryAttributes, PerVertexUvStaysPerVertexUnlessANewFaceHasNone) {
  Mesh s = test::attributed_grid();
  Mesh same;
  same.V = s.V;
  same.F = s.F;
  const Eigen::VectorXi vo = Eigen::VectorXi::LinSpaced(s.V.rows(), 0, static_cast<int>(s.V.rows()) - 1);
  const Eigen::VectorXi fo = Eigen::VectorXi::LinSpaced(s.F.rows(), 0, static_cast<int>(s.F.rows()) - 1);
  EXPECT_TRUE(carry_attributes(s, same, vo, fo).empty());
  EXPECT_EQ(same.uv, s.uv);
  EXPECT_EQ(same.face_texcoords.size(), 0);
  // One face repeated as a new face: uv becomes per-corner, the new face has none.
  Mesh more;
  more.V = s.V;
  more.F.resize(s.F.rows() + 1, 3);
  more.F << s.F, s.F.row(0).reverse();
  Eigen::VectorXi fo2(s.F.rows() + 1);
  fo2 << fo, -1;
  carry_attributes(s, more, vo, fo2);
  EXPECT_EQ(more.uv.size(), 0);
  ASSERT_EQ(more.face_texcoords.rows(), more.F.rows());
  EXPECT_EQ(more.texcoords.row(more.face_texcoords(3, 1)), s.uv.row(s.F(3, 1)));
  EXPECT_EQ(more.face_texcoords.row(s.F.rows()), Eigen::RowVector3i(-1, -1, -1));
}

TEST(CarryAttributes, BadOriginMapsAreRefused) {
  const Mesh s = square();
  Mesh r = s;
  EXPECT_THROW(carry_attributes(s, r, Eigen::VectorXi::Zero(3), Eigen::VectorXi::Zero(2)), InvalidInput);
  Eigen::VectorXi vo(4);
  vo << 0, 1, 2, 7;
  EXPECT_THROW(carry_attributes(s, r, vo, Eigen::VectorXi::Zero(2)), InvalidInput);
}

TEST(CornerUv, CollapsesToPerVertexOnlyWithoutSeams) {
  Mesh m = square();
  EXPECT_FALSE(corner_uv_to_vertex_uv(m));  // vertex 0 has (0,0) and (0.5,0): a seam
  EXPECT_EQ(m.face_texcoords.rows(), 2);
  m.face_texcoords << 0, 1, 2, 0, 2, 5;
  EXPECT_TRUE(corner_uv_to_vertex_uv(m));
  EXPECT_EQ(m.face_texcoords.size(), 0);
  ASSERT_EQ(m.uv.rows(), 4);
  EXPECT_EQ(m.uv.row(3), Eigen::RowVector2d(0, 1));
  EXPECT_EQ(m.uv.row(2), Eigen::RowVector2d(1, 1));
}

TEST(HasAttributes, OnlyVAndFIsNone) {
  Mesh m = test::grid(3);
  EXPECT_FALSE(has_attributes(m));
  m.group_names = {"a"};
  m.face_groups = Eigen::VectorXi::Zero(m.F.rows());
  EXPECT_TRUE(has_attributes(m));
}

TEST(DocumentAttributes, AreCopiedWholeAndNothingElse) {
  Mesh s = test::grid(3);
  s.material_libraries = {"a.mtl"};
  s.material_names = {"red", "blue"};
  s.group_names = {"g1"};
  s.object_names = {"o1"};
  s.position_type = ScalarType::Float32;
  Mesh r = test::grid(2);
  const Eigen::MatrixXd V = r.V;
  copy_document_attributes(s, r);
  EXPECT_EQ(r.material_libraries, s.material_libraries);
  EXPECT_EQ(r.material_names, s.material_names);
  EXPECT_EQ(r.group_names, s.group_names);
  EXPECT_EQ(r.object_names, s.object_names);
  EXPECT_EQ(r.position_type, s.position_type);
  EXPECT_EQ(r.V, V);  // geometry untouched
  EXPECT_EQ(r.vertex_colors.size(), 0);
}
