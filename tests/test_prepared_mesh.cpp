// PreparedMesh (prepared_mesh.h) and the stages that take it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/normal_filter.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/topology.h"
#include "msmesh/vertex_update.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(PreparedMesh, NormalisesToMeanEdgeLengthOneAndMapsBack) {
  Mesh m = test::grid(6, 0.2);
  m.V = (m.V * 7.5).rowwise() + Eigen::RowVector3d(3, -2, 1);
  const PreparedMesh p(m.V, m.F);
  const Topology t = build_topology(m.F, m.V.rows());
  EXPECT_EQ(p.edges(), t.edges);
  EXPECT_EQ(p.num_edges(), t.num_edges());
  EXPECT_NEAR(edge_lengths(p.positions(), p.topology()).mean(), 1.0, 1e-12);
  EXPECT_NEAR(p.positions().colwise().mean().norm(), 0.0, 1e-12);
  EXPECT_LT((p.to_input_units(p.positions()) - m.V).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(PreparedMesh, RefusesInvalidMeshesNamingTheCaller) {
  Mesh m = test::grid(3);
  m.F(0, 1) = 1000;
  try {
    PreparedMesh p(m.V, m.F, "my stage");
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("my stage: face 0 refers to vertex 1000"), std::string::npos) << e.what();
  }
  const Eigen::MatrixXd V = Eigen::MatrixXd::Zero(3, 3);
  const Eigen::MatrixXi F = (Eigen::MatrixXi(1, 3) << 0, 1, 2).finished();
  EXPECT_THROW(PreparedMesh(V, F), InvalidInput);  // no edge of positive length
}

TEST(PreparedMesh, WithoutFacesTheInputIsKept) {
  const Eigen::MatrixXd V = Eigen::MatrixXd::Random(4, 3);
  const PreparedMesh p(V, Eigen::MatrixXi(0, 3));
  EXPECT_EQ(p.positions(), V);
  EXPECT_EQ(p.scale(), 1.0);
  EXPECT_EQ(update_vertices(p, Eigen::MatrixXd(0, 3)).V, V);
  EXPECT_THROW(filter_normals(p), InvalidInput);
}

TEST(PreparedMesh, StagesGiveTheSameBitsAsFromVAndF) {
  const Mesh m = test::grid(8, 0.3);
  const PreparedMesh p(m.V, m.F);
  const NormalFilterResult a = filter_normals(m.V, m.F), b = filter_normals(p);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(b.edges, build_topology(m.F, m.V.rows()).edges);
  EXPECT_EQ(b.v.size(), b.edges.rows());
  const VertexUpdateResult c = update_vertices(m.V, m.F, a.normals, a.v), d = update_vertices(p, a.normals, a.v);
  EXPECT_EQ(c.V, d.V);
  EXPECT_EQ(c.change_history, d.change_history);
}

TEST(PreparedMesh, DenoiseCarriesTheEdgesOfItsField) {
  const Mesh m = test::grid(8, 0.3);
  const DenoiseResult r = denoise(m.V, m.F);
  EXPECT_EQ(r.edges, build_topology(m.F, m.V.rows()).edges);
  EXPECT_EQ(r.v.size(), r.edges.rows());
  EXPECT_GT(r.normal_report.iterations, 0);
  EXPECT_GT(r.vertex_report.iterations, 0);
}
