// The hole puncher (punch_holes.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/holes.h"
#include "msmesh/punch_holes.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"

using namespace msmesh;

TEST(HolesPunch, MakesTheRequestedNumberOfSimpleLoops) {
  const Mesh cube = make_cube(12);
  for (bool on_features : {false, true}) {
    const PunchResult p = punch_holes(cube.V, cube.F, 4, 2.5, 7, on_features);
    ASSERT_EQ(p.punched, 4);
    ASSERT_EQ(p.centers.size(), 4u);
    const std::vector<Hole> holes = find_holes(p.V, p.F);
    ASSERT_EQ(holes.size(), 4u);
    for (const Hole& h : holes) {
      EXPECT_TRUE(h.simple);
      EXPECT_FALSE(h.outer_boundary);
      EXPECT_GE(h.edges, 6);
    }
    // The index maps agree, rows are copied exactly, and no vertex is left unreferenced.
    ASSERT_EQ(p.vertex_map.size(), p.V.rows());
    for (Eigen::Index i = 0; i < p.V.rows(); ++i) {
      EXPECT_EQ(p.old_to_new(p.vertex_map(i)), i);
      EXPECT_TRUE(p.V.row(i) == cube.V.row(p.vertex_map(i)));
    }
    for (int c : p.centers) EXPECT_EQ(p.old_to_new(c), -1);
    const TopologySummary s = summarize_topology(p.F, build_topology(p.F, p.V.rows()));
    EXPECT_EQ(s.unreferenced_vertices, 0);
    EXPECT_EQ(s.non_manifold_vertices, 0);
    EXPECT_EQ(s.boundary_loops.size(), 4u);
    if (on_features)
      for (int c : p.centers) {  // a centre on a cube edge has two coordinates at ±1
        int planes = 0;
        for (int k = 0; k < 3; ++k) planes += std::abs(std::abs(cube.V(c, k)) - 1) < 1e-12;
        EXPECT_GE(planes, 2);
      }
  }
  // Same seed, same holes.
  EXPECT_EQ(punch_holes(cube.V, cube.F, 3, 2, 5).F, punch_holes(cube.V, cube.F, 3, 2, 5).F);
  EXPECT_THROW(punch_holes(cube.V, cube.F, -1, 2, 5), InvalidInput);
  EXPECT_THROW(punch_holes(cube.V, cube.F, 1, 0, 5), InvalidInput);
}
