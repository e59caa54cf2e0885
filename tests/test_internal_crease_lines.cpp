// Crease lines (src/crease_lines.h) and the shape rule that counts them: a cube's creases are
// one line network and count whole; short scattered creases (random-direction noise on a
// sphere) do not; the figure does not depend on the mesh's position, turn or scale.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "crease_lines.h"
#include "msmesh/geometry.h"
#include "msmesh/noise.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"

using namespace msmesh;

namespace {

// Edges whose two faces' normals differ by more than 30°.
std::vector<char> sharp_edges(const Mesh& m, const Topology& t) {
  const Eigen::MatrixXd N = face_normals(m.V, m.F);
  std::vector<char> crease(static_cast<std::size_t>(t.num_edges()), 0);
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (t.edge_is_interior[e] && N.row(t.edge_faces(e, 0)).dot(N.row(t.edge_faces(e, 1))) < std::cos(M_PI / 6))
      crease[static_cast<std::size_t>(e)] = 1;
  return crease;
}

double total(const Eigen::VectorXd& len, const std::vector<char>& crease) {
  double s = 0;
  for (Eigen::Index e = 0; e < len.size(); ++e)
    if (crease[static_cast<std::size_t>(e)]) s += len(e);
  return s;
}

}  // namespace

TEST(CreaseLines, ACubesCreasesAreOneLineAndCountWhole) {
  const Mesh cube = make_cube(16);
  const Topology t = build_topology(cube.F, cube.V.rows());
  const Eigen::VectorXd len = edge_lengths(cube.V, t);
  const std::vector<char> crease = sharp_edges(cube, t);
  const double all = total(len, crease), h = len.mean();
  const double side = cube.V.col(0).maxCoeff() - cube.V.col(0).minCoeff();
  ASSERT_NEAR(all, 12 * side, 1e-9 * all);  // the twelve edges of the cube
  EXPECT_DOUBLE_EQ(detail::crease_line_length(t, len, crease, cube.V.rows(), 40 * h), all);
  EXPECT_DOUBLE_EQ(detail::crease_line_length(t, len, crease, cube.V.rows(), 0.99 * all), all);
  EXPECT_EQ(detail::crease_line_length(t, len, crease, cube.V.rows(), 1.01 * all), 0.0);
}

TEST(CreaseLines, OnlyLinesLongEnoughCount) {
  // One edge of the cube (16 segments in a line) and five single edges apart from it and from
  // each other: the line counts whole up to its own length, the single edges never.
  const Mesh cube = make_cube(16);
  const Topology t = build_topology(cube.F, cube.V.rows());
  const Eigen::VectorXd len = edge_lengths(cube.V, t);
  const double lo_x = cube.V.col(0).minCoeff(), lo_y = cube.V.col(1).minCoeff();
  const double side = cube.V.col(0).maxCoeff() - lo_x;
  auto on_line = [&](int i) { return cube.V(i, 0) == lo_x && cube.V(i, 1) == lo_y; };
  std::vector<char> crease(static_cast<std::size_t>(t.num_edges()), 0);
  std::vector<char> taken(static_cast<std::size_t>(cube.V.rows()), 0);  // vertices of marked edges and their neighbours
  auto take = [&](int i) {
    taken[static_cast<std::size_t>(i)] = 1;
    for (Eigen::Index g = 0; g < t.num_edges(); ++g)
      for (int k = 0; k < 2; ++k)
        if (t.edges(g, k) == i) taken[static_cast<std::size_t>(t.edges(g, 1 - k))] = 1;
  };
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (on_line(t.edges(e, 0)) && on_line(t.edges(e, 1))) crease[static_cast<std::size_t>(e)] = 1;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (crease[static_cast<std::size_t>(e)]) {
      take(t.edges(e, 0));
      take(t.edges(e, 1));
    }
  int singles = 0;
  for (Eigen::Index e = 0; e < t.num_edges() && singles < 5; ++e) {
    const int a = t.edges(e, 0), b = t.edges(e, 1);
    if (taken[static_cast<std::size_t>(a)] || taken[static_cast<std::size_t>(b)]) continue;
    crease[static_cast<std::size_t>(e)] = 1;
    take(a);
    take(b);
    ++singles;
  }
  ASSERT_EQ(singles, 5);
  const double all = total(len, crease);
  ASSERT_GT(all, side * (1 + 1e-9));
  EXPECT_NEAR(detail::crease_line_length(t, len, crease, cube.V.rows(), 0.5 * side), side, 1e-9 * side);
  EXPECT_NEAR(detail::crease_line_length(t, len, crease, cube.V.rows(), 0.99 * side), side, 1e-9 * side);
  EXPECT_EQ(detail::crease_line_length(t, len, crease, cube.V.rows(), 1.01 * side), 0.0);
  EXPECT_DOUBLE_EQ(detail::crease_line_length(t, len, crease, cube.V.rows(), 0.0), all);
}

TEST(CreaseLines, TheShapeRuleCountsCreasesOnLines) {
  // The cube: every crease is on a line, so the two fractions agree and the class is cad.
  const Mesh cube = make_cube(24);
  const PresetChoice c = choose_preset(cube.V, cube.F);
  EXPECT_GT(c.sharp_fraction, 0.02);
  EXPECT_NEAR(c.crease_line_fraction, c.sharp_fraction, 1e-12);
  EXPECT_EQ(c.preset, "cad") << c.reason;
  EXPECT_NE(c.reason.find("on lines of 40 edges or more"), std::string::npos) << c.reason;
  // A sphere under heavy random-direction noise: creases, but short and scattered.
  const Mesh sphere = make_sphere(5);
  NoiseOptions no;
  no.sigma = 0.5;
  no.direction = NoiseDirection::Random;
  no.seed = 11;
  const Eigen::MatrixXd noisy = add_noise(sphere.V, sphere.F, no);
  const PresetChoice s = choose_preset(noisy, sphere.F);
  EXPECT_GT(s.sharp_fraction, 0.01) << s.reason;
  EXPECT_LT(s.crease_line_fraction, 0.2 * s.sharp_fraction) << s.reason;
  // Invariant under turn, scale and translation.
  Eigen::Matrix3d R;
  R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(3, -1, 2).normalized());
  const Eigen::MatrixXd moved = ((noisy * R.transpose()) * 250.0).rowwise() + Eigen::RowVector3d(-3, 8, 1);
  EXPECT_NEAR(choose_preset(moved, sphere.F).crease_line_fraction, s.crease_line_fraction, 1e-9);
}

TEST(CreaseLines, APatchSampleCountsLinesItCuts) {
  // 480K faces, measured on a patch sample (presets.cpp): the cube's edges are cut by the
  // patches' borders into pieces shorter than 40 edges, which still count as lines, as on the
  // whole mesh.
  const Mesh cube = make_cube(200);
  ASSERT_GT(cube.F.rows(), 400000);
  const ResolvedPreset r = resolve_preset("auto", cube.V, cube.F);
  ASSERT_GT(r.sample_faces, 0);
  ASSERT_GT(r.choice.sharp_fraction, 0.0);
  EXPECT_NEAR(r.choice.crease_line_fraction, r.choice.sharp_fraction, 1e-12);
  const PresetChoice whole = choose_preset(cube.V, cube.F);
  EXPECT_NEAR(whole.crease_line_fraction, whole.sharp_fraction, 1e-12);
}

namespace {

// A wavy sheet folded along lines x = const every `period` grid columns: a triangle wave of
// the given slope on both sides of each fold (dihedral 2·atan(slope)) on a surface curved in
// both directions, so that little of it is flat.
Mesh folded_sheet(int n, double slope, int period) {
  Mesh m;
  m.V.resize(n * n, 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double phase = std::fmod(double(i), double(period)) / period;
      const double wave = period / 2.0 * (1 - std::abs(2 * phase - 1));
      const double z = slope * wave + 2 * std::cos(2 * M_PI * j / 24.0) + std::cos(2 * M_PI * i / 30.0);
      m.V.row(i * n + j) << i, j, z;
    }
  m.F.resize(2 * (n - 1) * (n - 1), 3);
  Eigen::Index f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = (i + 1) * n + j;
      m.F.row(f++) << a, b, b + 1;
      m.F.row(f++) << a, b + 1, a + 1;
    }
  return m;
}

}  // namespace

TEST(CreaseLines, GentleLinesDoNotMakeAPart) {
  // Folds of ~60° on a curved sheet: long crease lines (more than the 3 % of the lines rule)
  // but none of them steep after the pre-smoothing, and little flat: organic ridges, smooth.
  const Mesh gentle = folded_sheet(80, 0.6, 8);
  const PresetChoice g = choose_preset(gentle.V, gentle.F);
  ASSERT_GE(g.crease_line_fraction, 0.03) << g.reason;
  ASSERT_LT(g.steep_line_fraction, 0.6 * g.crease_line_fraction) << g.reason;
  ASSERT_LT(g.flat_fraction, 0.5) << g.reason;
  EXPECT_EQ(g.preset, "smooth") << g.reason;
  EXPECT_NE(g.reason.find("% of them steep (< 60 %)"), std::string::npos) << g.reason;
  // The same sheet folded at ~100°: the lines are steep, a part's edges: cad.
  const Mesh steep = folded_sheet(80, 1.2, 8);
  const PresetChoice s = choose_preset(steep.V, steep.F);
  ASSERT_LT(s.flat_fraction, 0.5) << s.reason;
  ASSERT_GE(s.steep_line_fraction, 0.6 * s.crease_line_fraction) << s.reason;
  EXPECT_EQ(s.preset, "cad") << s.reason;
  EXPECT_NE(s.reason.find("% of them steep, >= 60 %"), std::string::npos) << s.reason;
}
