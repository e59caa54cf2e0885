// topology.h: edges with a fixed orientation and the sign sgn(e, τ), boundary, non-manifold
// and unreferenced counts, orientation defects, boundary loops and face components.
#include <gtest/gtest.h>

#include <vector>

#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Topology, EdgeCountsAndSigns) {
  const Mesh tet = test::tetrahedron();
  const Topology t = build_topology(tet.F, tet.V.rows());
  EXPECT_EQ(t.num_edges(), 6);
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    EXPECT_TRUE(t.edge_is_interior[e]);
    EXPECT_LT(t.edges(e, 0), t.edges(e, 1));
  }
  // sgn(e, τ): each interior edge is walked forwards by edge_faces(e,0) and backwards by (e,1).
  for (Eigen::Index f = 0; f < t.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int e = t.face_edges(f, k);
      const int from = tet.F(f, (k + 1) % 3);
      EXPECT_EQ(t.face_edge_signs(f, k), from == t.edges(e, 0) ? 1 : -1);
      EXPECT_EQ(t.edge_faces(e, t.face_edge_signs(f, k) > 0 ? 0 : 1), f);
    }

  const Mesh g = test::grid(3);
  const Topology tg = build_topology(g.F, g.V.rows());
  const TopologySummary s = summarize_topology(g.F, tg);
  EXPECT_EQ(s.boundary_edges, 12);
  EXPECT_EQ(s.boundary_loops.size(), 1u);
  EXPECT_EQ(s.boundary_loops[0].size(), 12u);
  EXPECT_EQ(s.components, 1);

  const Mesh fin = test::fin();
  const Topology tf = build_topology(fin.F, fin.V.rows());
  const TopologySummary sf = summarize_topology(fin.F, tf);
  EXPECT_EQ(sf.non_manifold_edges, 1);
  EXPECT_GE(sf.non_manifold_vertices, 2);
}

TEST(Topology, GridEdgesBoundaryAndEuler) {
  const int n = 5;
  const Mesh g = test::grid(n);
  const Topology t = build_topology(g.F, g.V.rows());
  EXPECT_EQ(t.num_vertices, g.V.rows());
  EXPECT_EQ(t.num_faces(), 2 * n * n);
  EXPECT_EQ(t.num_edges(), 3 * n * n + 2 * n);
  EXPECT_EQ(g.V.rows() - t.num_edges() + t.num_faces(), 1);  // Euler characteristic of a disk
  Eigen::Index boundary = 0;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    EXPECT_EQ(t.edge_is_interior[e], t.edge_face_count(e) == 2) << "edge " << e;
    if (t.edge_face_count(e) == 1) {
      ++boundary;
      EXPECT_EQ(t.edge_faces(e, 1), -1) << "a boundary edge has one face";
    }
  }
  EXPECT_EQ(boundary, 4 * n);
  // face_edges(f,k) is the edge opposite corner k, walked in the sign's direction.
  for (Eigen::Index f = 0; f < t.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int e = t.face_edges(f, k), a = g.F(f, (k + 1) % 3), b = g.F(f, (k + 2) % 3);
      if (t.face_edge_signs(f, k) > 0) {
        EXPECT_EQ(t.edges(e, 0), a);
        EXPECT_EQ(t.edges(e, 1), b);
      } else {
        EXPECT_EQ(t.edges(e, 0), b);
        EXPECT_EQ(t.edges(e, 1), a);
      }
    }
  const TopologySummary s = summarize_topology(g.F, t);
  EXPECT_EQ(s.boundary_edges, 4 * n);
  EXPECT_EQ(s.non_manifold_edges, 0);
  EXPECT_EQ(s.non_manifold_vertices, 0);
  EXPECT_EQ(s.unreferenced_vertices, 0);
  EXPECT_EQ(s.inconsistently_oriented_edges, 0);
  EXPECT_EQ(s.components, 1);
  ASSERT_EQ(s.boundary_loops.size(), 1u);
  EXPECT_EQ(s.boundary_loops[0].size(), static_cast<size_t>(4 * n));
}

TEST(Topology, ClosedMeshHasNoBoundary) {
  const Mesh tet = test::tetrahedron();
  const TopologySummary s = summarize_topology(tet.F, build_topology(tet.F, tet.V.rows()));
  EXPECT_EQ(s.boundary_edges, 0);
  EXPECT_TRUE(s.boundary_loops.empty());
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(tet.V.rows() - 6 + tet.F.rows(), 2);  // Euler characteristic of a sphere
}

TEST(Topology, NonManifoldEdgeHasThreeFacesAndNoGradient) {
  const Mesh fin = test::fin();
  const Topology t = build_topology(fin.F, fin.V.rows());
  Eigen::Index shared = -1;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (t.edges(e, 0) == 0 && t.edges(e, 1) == 1) shared = e;
  ASSERT_GE(shared, 0);
  EXPECT_EQ(t.edge_face_count(shared), 3);
  EXPECT_FALSE(t.edge_is_interior[shared]);
  const TopologySummary s = summarize_topology(fin.F, t);
  EXPECT_EQ(s.non_manifold_edges, 1);
  EXPECT_EQ(s.components, 1);
}

TEST(Topology, UnreferencedVerticesAndFlippedFacesAreCounted) {
  Mesh m = test::tetrahedron();
  m.V.conservativeResize(6, 3);
  m.V.bottomRows(2).setZero();
  const Topology t = build_topology(m.F, m.V.rows());
  EXPECT_EQ(t.num_vertices, 6);
  EXPECT_EQ(summarize_topology(m.F, t).unreferenced_vertices, 2);
  std::swap(m.F(0, 1), m.F(0, 2));  // one face against its three neighbours
  const Topology flipped = build_topology(m.F, m.V.rows());
  const TopologySummary s = summarize_topology(m.F, flipped);
  EXPECT_EQ(s.inconsistently_oriented_edges, 3);
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(flipped.edge_is_interior[flipped.face_edges(0, k)]);
}

TEST(Topology, FaceComponentsLabelEachPiece) {
  const Mesh m = test::join(test::tetrahedron(), test::grid(2), Eigen::RowVector3d(5, 0, 0));
  const Topology t = build_topology(m.F, m.V.rows());
  int count = 0;
  const Eigen::VectorXi labels = face_components(t, &count);
  ASSERT_EQ(labels.size(), m.F.rows());
  EXPECT_EQ(count, 2);
  EXPECT_EQ(summarize_topology(m.F, t).components, 2);
  for (Eigen::Index f = 1; f < 4; ++f) EXPECT_EQ(labels(f), labels(0));
  for (Eigen::Index f = 5; f < m.F.rows(); ++f) EXPECT_EQ(labels(f), labels(4));
  EXPECT_NE(labels(0), labels(4));
  EXPECT_EQ(labels.minCoeff(), 0);
  EXPECT_EQ(labels.maxCoeff(), 1);
  EXPECT_EQ(face_components(t).size(), m.F.rows());  // the count is optional
}

TEST(Topology, NoFaces) {
  const Topology t = build_topology(Eigen::MatrixXi(0, 3), 3);
  EXPECT_EQ(t.num_edges(), 0);
  EXPECT_EQ(t.num_faces(), 0);
  const TopologySummary s = summarize_topology(Eigen::MatrixXi(0, 3), t);
  EXPECT_EQ(s.unreferenced_vertices, 3);
  EXPECT_EQ(s.components, 0);
}
