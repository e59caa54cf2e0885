// Hole finding (holes.h): boundary loops, the outer-boundary rule, self-touching boundaries.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/holes.h"
#include "msmesh/punch_holes.h"
#include "msmesh/shapes.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(HolesFind, ClosedMeshHasNone) {
  const Mesh cube = make_cube(4);
  EXPECT_TRUE(find_holes(cube.V, cube.F).empty());
}

TEST(HolesFind, GridRimIsTheOuterBoundaryAndAHoleIsNot) {
  // A 10×10 grid with the four middle cells removed: a rim (40 edges) and a hole (8 edges).
  const Mesh g = test::grid_with_hole();
  const Eigen::MatrixXi& F = g.F;
  const std::vector<Hole> holes = find_holes(g.V, F);
  ASSERT_EQ(holes.size(), 2u);
  int outer = 0;
  for (const Hole& h : holes) {
    EXPECT_TRUE(h.simple);
    EXPECT_EQ(h.loop.size(), static_cast<size_t>(h.edges));
    if (h.outer_boundary) {
      ++outer;
      EXPECT_EQ(h.edges, 40);
      EXPECT_NEAR(h.diameter, std::sqrt(2.0) / mean_edge_length(g.V, F), 1e-9);  // corner to corner
    } else {
      EXPECT_EQ(h.edges, 8);
    }
  }
  EXPECT_EQ(outer, 1);
}

TEST(HolesFind, LargeHolesInAClosedMeshAreNotOuterBoundaries) {
  // Holes of radius 6 edges on a cube of 16 × 16 quads per side: each spans more than half of
  // the bounding-box diagonal, but only a small part of the surface.
  const Mesh cube = make_cube(16);
  const PunchResult p = punch_holes(cube.V, cube.F, 3, 6, 1, true);
  ASSERT_EQ(p.punched, 3);
  for (const Hole& h : find_holes(p.V, p.F)) {
    EXPECT_FALSE(h.outer_boundary) << "diameter " << h.diameter << ", spanned area " << h.spanned_area;
    EXPECT_GT(h.spanned_area, 0);
  }
}

TEST(HolesFind, BoundaryTouchingItselfIsReported) {
  int touching = -1;
  const Mesh m = test::grid_with_touching_holes(&touching);
  const std::vector<Hole> holes = find_holes(m.V, m.F);
  int non_simple = 0;
  for (const Hole& h : holes)
    if (!h.simple) {
      ++non_simple;
      EXPECT_EQ(h.touching_vertex, touching);
      EXPECT_EQ(h.edges, 8);
      EXPECT_EQ(h.loop.size(), 8u);  // the closed walk visits the touching vertex twice
    }
  EXPECT_EQ(non_simple, 1);
}
