// mesh_coloring.h: error, edge-field, label and vertex colourings with their legends.
#include <gtest/gtest.h>

#include "image_test_helpers.h"
#include "msmesh/color_map.h"
#include "msmesh/errors.h"
#include "msmesh/mesh_coloring.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(MeshColoring, ErrorScaleIsARoundedPercentile) {
  Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(100, 0.0, 3.3);
  EXPECT_DOUBLE_EQ(error_scale(x), 5.0);  // 98th percentile 3.23 → 5
  x(99) = 170;                            // one wild face does not move it
  EXPECT_DOUBLE_EQ(error_scale(x), 5.0);
  EXPECT_DOUBLE_EQ(error_scale(Eigen::VectorXd::Constant(10, 0.15)), 0.2);
  EXPECT_DOUBLE_EQ(error_scale(Eigen::VectorXd()), 1.0);
}

TEST(MeshColoring, ErrorColoringClampsAndSaysSo) {
  Eigen::VectorXd a(3);
  a << 0, 1, 4;
  const Coloring c = error_coloring(a, 2);
  ASSERT_EQ(c.style.face_colors.rows(), 3);
  EXPECT_TRUE(c.style.face_colors.row(0).isApprox(heat_color(0).transpose()));
  EXPECT_TRUE(c.style.face_colors.row(2).isApprox(heat_color(1).transpose()));
  EXPECT_TRUE(c.has_bar);
  EXPECT_TRUE(c.bar.max_is_clamped);
  EXPECT_DOUBLE_EQ(c.bar.max, 2);
}

TEST(MeshColoring, FieldAndLabels) {
  const Mesh g = test::grid(2);
  const Topology t = build_topology(g.F, g.V.rows());
  Eigen::VectorXd v = Eigen::VectorXd::Ones(t.num_edges());
  v(0) = 0;
  const Coloring f = field_coloring(g.F, g.V.rows(), v);
  EXPECT_EQ(f.style.lines.rows(), 1) << "only the feature edge is drawn";
  EXPECT_THROW(field_coloring(g.F, g.V.rows(), Eigen::VectorXd::Ones(3)), InvalidInput);
  Eigen::VectorXi labels = Eigen::VectorXi::Zero(g.F.rows());
  labels(0) = 1;
  const Coloring l = label_coloring(g.F, g.V.rows(), labels);
  EXPECT_TRUE(l.style.face_colors.row(0).isApprox(label_color(1).transpose()));
  EXPECT_GT(l.style.lines.rows(), 0);
  EXPECT_THROW(label_coloring(g.F, g.V.rows(), Eigen::VectorXi::Zero(2)), InvalidInput);
}

TEST(MeshColoring, VertexColorsAreChecked) {
  const Coloring c = vertex_coloring(Eigen::MatrixXd::Constant(4, 3, 0.5), 4);
  EXPECT_EQ(c.style.vertex_colors.rows(), 4);
  EXPECT_FALSE(c.has_bar);
  EXPECT_THROW(vertex_coloring(Eigen::MatrixXd::Constant(3, 3, 0.5), 4), InvalidInput);
  EXPECT_THROW(vertex_coloring(Eigen::MatrixXd::Constant(4, 3, 2.0), 4), InvalidInput);
}

TEST(MeshColoring, ColorBarAddsAStrip) {
  const Image picture(200, 100);
  Coloring c = error_coloring(Eigen::VectorXd::Constant(2, 1.0), 0);
  const Image with = add_color_bar(picture, c);
  EXPECT_EQ(with.width, 200);
  EXPECT_GT(with.height, 100);
  c.has_bar = false;
  EXPECT_EQ(add_color_bar(picture, c).height, 100);
}
