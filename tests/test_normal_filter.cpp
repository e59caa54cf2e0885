// normal_filter.h (Algorithm 1): unit normals and an edge field in [0, 1] that is low on
// creases and high on flat parts; a flat mesh stays flat; the energy (15) drops; MSTV
// (reweight off) differs from NMSTV; bad options, weights and input normals are refused.
#include <gtest/gtest.h>

#include <string>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/normal_filter.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(NormalFilter, UnitNormalsAndAnEdgeFieldPerEdge) {
  const Mesh m = test::noisy_cube(6, 0.2);
  const NormalFilterResult r = filter_normals(m.V, m.F);
  const Topology t = build_topology(m.F, m.V.rows());
  ASSERT_EQ(r.normals.rows(), m.F.rows());
  ASSERT_EQ(r.v.size(), t.num_edges());
  for (Eigen::Index f = 0; f < r.normals.rows(); ++f) EXPECT_NEAR(r.normals.row(f).norm(), 1.0, 1e-9);
  EXPECT_GE(r.v.minCoeff(), -1e-9);
  EXPECT_LE(r.v.maxCoeff(), 1 + 1e-9);
  EXPECT_GE(r.iterations, 1);
  EXPECT_EQ(r.change_history.size(), static_cast<size_t>(r.iterations));
  EXPECT_EQ(r.residual_history.size(), static_cast<size_t>(r.iterations));
  // Closer to the clean cube's normals than the noisy input.
  const Mesh c = make_cube(6);
  const Eigen::MatrixXd clean = face_normals(c.V, c.F);
  EXPECT_LT((r.normals - clean).norm(), 0.5 * (face_normals(m.V, m.F) - clean).norm());
}

TEST(NormalFilter, FlatGridStaysFlat) {
  const Mesh g = test::grid(6);
  const NormalFilterResult r = filter_normals(g.V, g.F);
  for (Eigen::Index f = 0; f < r.normals.rows(); ++f)
    EXPECT_TRUE(r.normals.row(f).isApprox(Eigen::RowVector3d(0, 0, 1), 1e-6)) << "face " << f;
}

TEST(NormalFilter, EnergyDropsWhenRecorded) {
  const Mesh m = test::noisy_cube(5, 0.2);
  NormalFilterOptions o;
  o.record_energy = true;
  o.tolerance = 0;
  o.max_iterations = 10;
  const NormalFilterResult r = filter_normals(m.V, m.F, o);
  ASSERT_EQ(r.energy_history.size(), 10u);
  EXPECT_LT(r.energy_history.back(), r.energy_history.front());
  // nmstv_energy at the input normals with v = 1 everywhere is the fidelity-free starting point.
  const Eigen::MatrixXd N0 = face_normals(m.V, m.F);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(r.v.size());
  EXPECT_GT(nmstv_energy(m.V, m.F, N0, ones, N0, o), 0.0);
  EXPECT_TRUE(std::isfinite(nmstv_energy(m.V, m.F, r.normals, r.v, N0, o)));
}

TEST(NormalFilter, MstvIsNmstvWithoutReweighting) {
  const Mesh m = test::noisy_cube(5, 0.2);
  NormalFilterOptions o;
  const NormalFilterResult nmstv = filter_normals(m.V, m.F, o);
  o.reweight = false;
  const NormalFilterResult mstv = filter_normals(m.V, m.F, o);
  EXPECT_GT((mstv.normals - nmstv.normals).norm(), 1e-6);
}

TEST(NormalFilter, RefusesBadOptionsWeightsAndInputNormals) {
  const Mesh m = test::grid(3);
  for (auto set :
       {+[](NormalFilterOptions& o) { o.alpha = 0; }, +[](NormalFilterOptions& o) { o.epsilon = -1; },
        +[](NormalFilterOptions& o) { o.relaxation = 2; }, +[](NormalFilterOptions& o) { o.max_iterations = 0; }}) {
    NormalFilterOptions o;
    set(o);
    EXPECT_THROW(o.validate(), InvalidInput);
    EXPECT_THROW(filter_normals(m.V, m.F, o), InvalidInput);
  }
  EXPECT_NO_THROW(NormalFilterOptions{}.validate());
  NormalFilterWeights w;
  w.face_alpha = Eigen::VectorXd::Ones(3);
  try {
    filter_normals(m.V, m.F, {}, w);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("normal filtering: "), std::string::npos) << e.what();
  }
  w.face_alpha = -Eigen::VectorXd::Ones(m.F.rows());
  EXPECT_THROW(filter_normals(m.V, m.F, {}, w), InvalidInput);
  EXPECT_THROW(filter_normals(m.V, m.F, {}, {}, {}, Eigen::MatrixXd::Zero(2, 3)), InvalidInput);
  EXPECT_THROW(filter_normals(m.V, Eigen::MatrixXi(0, 3)), InvalidInput);
}

TEST(NormalFilter, ProgressReportsEachIterationAndCanCancel) {
  const Mesh m = test::noisy_cube(3, 0.2);
  NormalFilterOptions o;
  o.tolerance = 0;
  o.max_iterations = 3;
  int calls = 0;
  filter_normals(m.V, m.F, o, {}, [&](const ProgressEvent& e) {
    ++calls;
    EXPECT_EQ(e.stage, "normal filtering");
    EXPECT_EQ(e.iteration, calls);
    EXPECT_EQ(e.max_iterations, 3);
    EXPECT_GE(e.residual, 0.0);
    return true;
  });
  EXPECT_EQ(calls, 3);
  EXPECT_THROW(filter_normals(m.V, m.F, o, {}, [](const ProgressEvent&) { return false; }), Cancelled);
}
