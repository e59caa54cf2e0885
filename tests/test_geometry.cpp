// geometry.h: areas, normals, barycentres, edge and corner-line lengths, vertex normals, the
// bounding box and dihedral angles against values known in closed form; how they scale;
// degenerate faces and isolated vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/threads.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Geometry, RightTriangleInClosedForm) {
  const Mesh m = test::right_triangle();
  EXPECT_DOUBLE_EQ(face_areas(m.V, m.F)(0), 0.5);
  EXPECT_TRUE(face_normals(m.V, m.F).row(0).isApprox(Eigen::RowVector3d(0, 0, 1)));
  EXPECT_TRUE(face_barycenters(m.V, m.F).row(0).isApprox(Eigen::RowVector3d(1.0 / 3, 1.0 / 3, 0)));
  const Eigen::MatrixXd lines = corner_line_lengths(m.V, m.F);
  ASSERT_EQ(lines.rows(), 1);
  ASSERT_EQ(lines.cols(), 3);
  EXPECT_NEAR(lines(0, 0), std::sqrt(2.0) / 3, 1e-15);
  EXPECT_NEAR(lines(0, 1), std::sqrt(5.0) / 3, 1e-15);
  EXPECT_NEAR(lines(0, 2), std::sqrt(5.0) / 3, 1e-15);
  const Eigen::VectorXd len = edge_lengths(m.V, build_topology(m.F, 3));
  EXPECT_NEAR(len.sum(), 2 + std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(mean_edge_length(m.V, m.F), (2 + std::sqrt(2.0)) / 3, 1e-15);
  EXPECT_NEAR(bounding_box_diagonal(m.V), std::sqrt(2.0), 1e-15);
  // Reversing the corners flips the normal, not the area.
  Mesh r = m;
  std::swap(r.F(0, 1), r.F(0, 2));
  EXPECT_TRUE(face_normals(r.V, r.F).row(0).isApprox(Eigen::RowVector3d(0, 0, -1)));
  EXPECT_DOUBLE_EQ(face_areas(r.V, r.F)(0), 0.5);
}

TEST(Geometry, RegularTetrahedron) {
  const Mesh t = test::tetrahedron();  // edge length 2√2
  const Eigen::VectorXd a = face_areas(t.V, t.F);
  for (Eigen::Index f = 0; f < 4; ++f) EXPECT_NEAR(a(f), 2 * std::sqrt(3.0), 1e-12);
  // A closed surface: the area-weighted normals sum to zero, and each points away from the centre.
  const Eigen::MatrixXd n = face_normals(t.V, t.F), c = face_barycenters(t.V, t.F);
  EXPECT_LT((a.asDiagonal() * n).colwise().sum().norm(), 1e-12);
  for (Eigen::Index f = 0; f < 4; ++f) {
    EXPECT_NEAR(n.row(f).norm(), 1.0, 1e-12);
    EXPECT_GT(n.row(f).dot(c.row(f)), 0);
  }
  const Topology topo = build_topology(t.F, t.V.rows());
  const Eigen::VectorXd len = edge_lengths(t.V, topo);
  ASSERT_EQ(len.size(), 6);
  for (Eigen::Index e = 0; e < 6; ++e) EXPECT_NEAR(len(e), 2 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(mean_edge_length(t.V, t.F), 2 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(bounding_box_diagonal(t.V), 2 * std::sqrt(3.0), 1e-12);
  // The angle between the normals of two faces of a regular tetrahedron is acos(-1/3).
  const Eigen::VectorXd dihedral = dihedral_angles(t.V, t.F, topo);
  for (Eigen::Index e = 0; e < 6; ++e) EXPECT_NEAR(dihedral(e), std::acos(-1.0 / 3), 1e-12);
  // By symmetry the vertex normals point along the vertices' positions.
  const Eigen::MatrixXd vn = vertex_normals(t.V, t.F);
  for (Eigen::Index i = 0; i < 4; ++i) EXPECT_TRUE(vn.row(i).isApprox(t.V.row(i).normalized(), 1e-12));
}

TEST(Geometry, FlatGridHasZeroDihedralAnglesAndUnitArea) {
  const Mesh g = test::grid(6);
  const Topology topo = build_topology(g.F, g.V.rows());
  EXPECT_NEAR(face_areas(g.V, g.F).sum(), 1.0, 1e-12);
  EXPECT_LT(dihedral_angles(g.V, g.F, topo).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::MatrixXd vn = vertex_normals(g.V, g.F);
  for (Eigen::Index i = 0; i < vn.rows(); ++i) EXPECT_TRUE(vn.row(i).isApprox(Eigen::RowVector3d(0, 0, 1)));
}

TEST(Geometry, LengthsScaleLinearlyAndAreasQuadratically) {
  const Mesh g = test::grid(4, 0.3);
  const double s = 3.5;
  const Eigen::MatrixXd V2 = s * g.V;
  const Topology topo = build_topology(g.F, g.V.rows());
  EXPECT_TRUE(face_areas(V2, g.F).isApprox(s * s * face_areas(g.V, g.F)));
  EXPECT_TRUE(edge_lengths(V2, topo).isApprox(s * edge_lengths(g.V, topo)));
  EXPECT_TRUE(corner_line_lengths(V2, g.F).isApprox(s * corner_line_lengths(g.V, g.F)));
  EXPECT_NEAR(mean_edge_length(V2, g.F), s * mean_edge_length(g.V, g.F), 1e-12);
  EXPECT_NEAR(bounding_box_diagonal(V2), s * bounding_box_diagonal(g.V), 1e-12);
  EXPECT_TRUE(face_normals(V2, g.F).isApprox(face_normals(g.V, g.F)));
  EXPECT_TRUE(dihedral_angles(V2, g.F, topo).isApprox(dihedral_angles(g.V, g.F, topo)));
}

TEST(Geometry, DegenerateFacesIsolatedVerticesAndNoFaces) {
  Mesh m = test::right_triangle();
  m.V.conservativeResize(5, 3);
  m.V.row(3) << 2, 0, 0;  // collinear with vertices 0 and 1
  m.V.row(4) << 9, 9, 9;  // isolated
  m.F.conservativeResize(2, 3);
  m.F.row(1) << 0, 1, 3;
  EXPECT_EQ(face_areas(m.V, m.F)(1), 0.0);
  EXPECT_EQ(face_normals(m.V, m.F).row(1), Eigen::RowVector3d::Zero());
  const Eigen::MatrixXd vn = vertex_normals(m.V, m.F);
  EXPECT_EQ(vn.row(4), Eigen::RowVector3d::Zero());
  EXPECT_TRUE(vn.row(2).isApprox(Eigen::RowVector3d(0, 0, 1)));
  EXPECT_TRUE(vn.row(3).allFinite());
  EXPECT_EQ(mean_edge_length(m.V, Eigen::MatrixXi(0, 3)), 0.0);
}

TEST(Geometry, MeanEdgeLengthIsTheMeanOverTheTopologysEdgesToTheLastBit) {
  // The same edges in the same order as build_topology, so the same sum: the scale every
  // stage normalises by must not move by a bit. A noisy closed mesh, a grid (boundary), and
  // one with a vertex no face uses; an index out of range is refused as before.
  const Mesh cube = test::noisy_cube(5, 0.3);
  Mesh grid = test::noisy(test::grid(6, 0.2), 0.05);
  for (const Mesh* m : {&cube, static_cast<const Mesh*>(&grid)})
    EXPECT_EQ(mean_edge_length(m->V, m->F), edge_lengths(m->V, build_topology(m->F, m->V.rows())).mean());
  Eigen::MatrixXd V = grid.V;
  V.conservativeResize(V.rows() + 1, 3);
  V.row(V.rows() - 1) << 100, 100, 100;
  EXPECT_EQ(mean_edge_length(V, grid.F), edge_lengths(grid.V, build_topology(grid.F, grid.V.rows())).mean());
  Eigen::MatrixXi bad = grid.F;
  bad(0, 0) = -1;
  EXPECT_THROW(mean_edge_length(grid.V, bad), InvalidInput);
}

TEST(Geometry, MeanEdgeLengthIsTheSameBitsAtEveryThreadCount) {
  // 19200 faces, 9602 vertices: large enough that the edges are sorted and measured in parallel.
  const Mesh cube = test::noisy_cube(40, 0.3);
  const double reference = edge_lengths(cube.V, build_topology(cube.F, cube.V.rows())).mean();
  const int before = threads();
  for (const int n : {1, 2, 3}) {
    SCOPED_TRACE(n);
    set_threads(n);
    EXPECT_EQ(mean_edge_length(cube.V, cube.F), reference);
  }
  set_threads(before);
}
