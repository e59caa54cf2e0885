// repair.h: repair_mesh merges duplicate vertices without renumbering, removes degenerate,
// zero-area and duplicate faces keeping face order, orients components (closed ones outwards),
// counts non-orientable ones and splits non-manifold vertices and edges (docs/robustness.md,
// "Repair"). `msmesh repair`: cli/test_repair_cli.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "msmesh/repair.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Repair, MergesDuplicateVerticesWithoutRenumbering) {
  Mesh m = test::tetrahedron();
  m.V.conservativeResize(6, 3);
  m.V.row(4) = m.V.row(1);                                   // exact copy
  m.V.row(5) = m.V.row(2) + Eigen::RowVector3d(1e-4, 0, 0);  // close copy
  m.F(1, 2) = 4;                                             // face 1 uses the exact copy
  m.F(3, 2) = 5;                                             // face 3 uses the close copy
  Mesh exact = m;
  RepairReport r = repair_mesh(exact);
  EXPECT_EQ(r.merged_vertices, 1);
  EXPECT_EQ(exact.V, m.V) << "the vertex array is kept";
  EXPECT_EQ(exact.F(1, 2), 1);
  EXPECT_EQ(exact.F(3, 2), 5);
  Mesh welded = m;
  RepairOptions o;
  o.weld_tolerance = 0.01;
  r = repair_mesh(welded, o);
  EXPECT_EQ(r.merged_vertices, 2);
  EXPECT_EQ(welded.F, test::tetrahedron().F);
  EXPECT_EQ(r.unreferenced_vertices, 2);
  o.remove_unreferenced = true;
  Mesh compact = m;
  r = repair_mesh(compact, o);
  EXPECT_EQ(r.unreferenced_vertices_removed, 2);
  EXPECT_EQ(compact.V, test::tetrahedron().V);
  EXPECT_EQ(r.vertex_map, (Eigen::VectorXi(6) << 0, 1, 2, 3, -1, -1).finished());
}

TEST(Repair, RemovesDegenerateZeroAreaAndDuplicateFacesKeepingFaceOrder) {
  Mesh m = test::grid(3);
  const Eigen::Index nf = m.F.rows();
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) = 0.5 * (m.V.row(0) + m.V.row(1));  // on the edge 0-1
  m.F.conservativeResize(nf + 4, 3);
  m.F.row(nf) << 0, 1, static_cast<int>(m.V.rows() - 1);  // zero area
  m.F.row(nf + 1) = m.F.row(2);                           // duplicate
  m.F.row(nf + 2) << 3, 3, 4;                             // repeats a vertex
  m.F.row(nf + 3) << m.F(4, 2), m.F(4, 1), m.F(4, 0);     // reversed duplicate
  RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.zero_area_faces_removed, 1);
  EXPECT_EQ(r.duplicate_faces_removed, 2);
  EXPECT_EQ(r.degenerate_faces_removed, 1);
  EXPECT_EQ(r.flipped_faces, 0);
  EXPECT_EQ(m.F, test::grid(3).F);
  EXPECT_EQ(r.face_origin, Eigen::VectorXi::LinSpaced(nf, 0, static_cast<int>(nf - 1)));
  EXPECT_EQ(r.actions().size(), 3u);
  // A clean mesh is left alone.
  Mesh clean = test::grid(3);
  r = repair_mesh(clean);
  EXPECT_FALSE(r.changed());
  EXPECT_TRUE(r.actions().empty());
}

TEST(Repair, OrientsComponentsClosedOnesOutwards) {
  Mesh inside_out = test::tetrahedron();
  for (Eigen::Index f = 0; f < 4; ++f) std::swap(inside_out.F(f, 1), inside_out.F(f, 2));
  Mesh two = test::join(inside_out, test::grid(4), Eigen::RowVector3d(5, 0, 0));
  std::swap(two.F(6, 1), two.F(6, 2));  // one face of the grid flipped
  const RepairReport r = repair_mesh(two);
  EXPECT_EQ(r.flipped_faces, 5);
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(two.F.topRows(4), test::tetrahedron().F);
  EXPECT_EQ(two.F.bottomRows(32), (test::grid(4).F.array() + 4).matrix());
}

TEST(Repair, NonOrientableComponentIsCounted) {
  // A Moebius strip: a band of 5 quads whose ends are joined with a half twist.
  const int n = 5;
  Mesh m;
  m.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    for (int s = 0; s < 2; ++s) {
      const double w = s ? 0.3 : -0.3, h = t / 2;
      m.V.row(2 * i + s) << (1 + w * std::cos(h)) * std::cos(t), (1 + w * std::cos(h)) * std::sin(t), w * std::sin(h);
    }
  }
  m.F.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    int a = 2 * i, b = 2 * i + 1, c = 2 * (i + 1), d = 2 * (i + 1) + 1;
    if (i == n - 1) c = 1, d = 0;  // the twist
    m.F.row(2 * i) << a, c, b;
    m.F.row(2 * i + 1) << b, c, d;
  }
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.non_orientable_components, 1);
  EXPECT_TRUE(m.V.allFinite());
}

TEST(Repair, SplitsNonManifoldVerticesAndEdgesCarryingAttributes) {
  Mesh fin = test::fin();
  fin.vertex_colors = Eigen::MatrixXd::Random(5, 3).cwiseAbs();
  RepairOptions o;
  o.split_non_manifold = true;
  RepairReport r = repair_mesh(fin, o);
  EXPECT_EQ(r.split_vertices, 4);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_EQ(r.non_manifold_vertices, 0);
  EXPECT_EQ(r.components, 3);
  ASSERT_EQ(fin.V.rows(), 9);
  EXPECT_EQ(fin.V.topRows(5), test::fin().V) << "existing vertices keep their index";
  ASSERT_EQ(fin.vertex_colors.rows(), 9);
  for (Eigen::Index i = 5; i < 9; ++i) {
    Eigen::Index src;
    (test::fin().V.rowwise() - fin.V.row(i)).rowwise().squaredNorm().minCoeff(&src);
    EXPECT_EQ(fin.vertex_colors.row(i), fin.vertex_colors.row(src));
  }
  // A bow tie: two fans around one vertex.
  Mesh bow;
  bow.V.resize(5, 3);
  bow.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0;
  bow.F.resize(2, 3);
  bow.F << 0, 1, 2, 0, 3, 4;
  r = repair_mesh(bow, o);
  EXPECT_EQ(r.split_vertices, 1);
  EXPECT_EQ(bow.F(1, 0), 5);
}

TEST(Repair, AttributesFollowTheirVerticesFacesAndCorners) {
  // Flipped faces with per-corner texture coordinates (a seam), face colours, materials, a
  // duplicate face and a vertex property: after repair each corner keeps the texture
  // coordinates of its vertex in that face, each face its colour and material.
  Mesh m = test::grid_with_flipped_faces();
  const Eigen::Index nv = m.V.rows(), nf = m.F.rows();
  m.texcoords.resize(2 * nv, 2);
  m.face_texcoords.resize(nf, 3);
  m.face_colors.resize(nf, 3);
  m.material_names = {"a", "b"};
  m.face_materials.resize(nf);
  for (Eigen::Index i = 0; i < nv; ++i) {
    m.texcoords.row(i) = m.V.row(i).head<2>();
    m.texcoords.row(nv + i) = m.V.row(i).head<2>() + Eigen::RowVector2d(5, 0);
  }
  for (Eigen::Index f = 0; f < nf; ++f) {
    const int chart = f % 2;
    for (int k = 0; k < 3; ++k) m.face_texcoords(f, k) = m.F(f, k) + chart * static_cast<int>(nv);
    m.face_colors.row(f) << f / double(nf), 0.5, chart;
    m.face_materials(f) = chart;
  }
  m.vertex_properties.push_back({"q", Eigen::VectorXd::LinSpaced(nv, 0, 1), ScalarType::Float32});
  const Mesh before = m;
  const RepairReport r = repair_mesh(m);
  ASSERT_GT(r.flipped_faces, 0);
  ASSERT_EQ(m.face_texcoords.rows(), m.F.rows());
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const int o = r.face_origin(f);
    EXPECT_EQ(m.face_colors.row(f), before.face_colors.row(o));
    EXPECT_EQ(m.face_materials(f), before.face_materials(o));
    for (int k = 0; k < 3; ++k) {
      // The source corner of the same vertex (vertex order is kept: no renumbering here).
      int j = 0;
      while (j < 3 && before.F(o, j) != m.F(f, k)) ++j;
      ASSERT_LT(j, 3);
      EXPECT_EQ(m.texcoords.row(m.face_texcoords(f, k)), before.texcoords.row(before.face_texcoords(o, j)));
    }
  }
  EXPECT_TRUE(m.vertex_properties[0].values == before.vertex_properties[0].values);
  EXPECT_TRUE(r.attribute_notes.empty());
}
