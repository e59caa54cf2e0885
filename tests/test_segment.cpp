// Segmentation (paper §6.3) and feature lines: patch counts and crease fractions on the
// procedural CAD-like shapes, clean and noisy; label validity; invariance; the Rand index of
// clean against noisy public CAD meshes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/noise.h"
#include "msmesh/segment.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

// Resolution per shape: cube 1,200 faces; cylinder 2,404 (50 segments around, 7.2° between
// side facets, well inside the 15° smooth angle); fandisk-like part 4,648.
int resolution_of(const std::string& shape) { return shape == "cube" ? 10 : shape == "cylinder" ? 16 : 20; }

// Segments the method may lose at a noise level. The cube's and the cylinder's creases are
// all 90°: none. The fandisk-like part has a weak 32° crease along the narrow strip between
// its cylindrical band and a flat face; the cad-preset v field puts it near the p = 1/2
// decision level even without noise (normalised v ≈ 0.45), so from σ = 0.2 on the strip
// merges into a neighbour for most seeds (seeds 1–6 and 11: σ = 0.1 9 segments always,
// σ = 0.2 8 or 9, σ = 0.3 8 or 9; docs/segmentation.md). Never more segments than patches.
int allowed_missing(const std::string& shape, double sigma) { return shape == "fandisk" && sigma >= 0.2 ? 1 : 0; }

Eigen::MatrixXd noisy(const Mesh& m, double sigma, std::uint64_t seed) {
  if (sigma == 0) return m.V;
  NoiseOptions no;
  no.sigma = sigma;
  no.seed = seed;
  return add_noise(m.V, m.F, no);
}

struct CutStats {
  int cut = 0;        // interior edges between different labels
  int on_crease = 0;  // of those, edges with a clean dihedral angle above 30°
  double fraction() const { return cut ? double(on_crease) / cut : 1.0; }
};

CutStats cut_stats(const Mesh& clean, const Eigen::VectorXi& labels) {
  const Topology t = build_topology(clean.F, clean.V.rows());
  const Eigen::VectorXd dihedral = dihedral_angles(clean.V, clean.F, t);
  CutStats s;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    if (!t.edge_is_interior[e] || labels(t.edge_faces(e, 0)) == labels(t.edge_faces(e, 1))) continue;
    ++s.cut;
    if (dihedral(e) > M_PI / 6) ++s.on_crease;
  }
  return s;
}

// The face adjacency graph over interior edges (for validity checks).
Eigen::MatrixXi face_graph(const Mesh& m) {
  const Topology t = build_topology(m.F, m.V.rows());
  std::vector<std::array<int, 2>> e;
  for (Eigen::Index k = 0; k < t.num_edges(); ++k)
    if (t.edge_is_interior[k]) e.push_back({t.edge_faces(k, 0), t.edge_faces(k, 1)});
  Eigen::MatrixXi E(static_cast<Eigen::Index>(e.size()), 2);
  for (size_t k = 0; k < e.size(); ++k) E.row(k) << e[k][0], e[k][1];
  return E;
}

void expect_valid(const Mesh& m, const SegmentResult& r) {
  ASSERT_EQ(r.labels.size(), m.F.rows());
  EXPECT_EQ(r.labels.minCoeff(), 0);
  EXPECT_EQ(r.labels.maxCoeff(), r.count - 1);
  ASSERT_EQ(r.areas.size(), r.count);
  for (int i = 1; i < r.count; ++i) EXPECT_GE(r.areas(i - 1), r.areas(i));
  EXPECT_NEAR(r.areas.sum(), face_areas(m.V, m.F).sum(), 1e-9 * r.areas.sum());
  EXPECT_TRUE(is_valid_multicut(m.F.rows(), face_graph(m), r.labels)) << "a segment is not edge-connected";
  EXPECT_GE(r.v_normalized.minCoeff(), 0.0);
  EXPECT_LE(r.v_normalized.maxCoeff(), 1.0);
}

}  // namespace

// ---- procedural shapes, clean and noisy ------------------------------------------------------

class SegmentShapes : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(SegmentShapes, FindsThePatchesAndCutsOnCreases) {
  const auto& [shape, sigma] = GetParam();
  const Mesh clean = make_shape(shape, resolution_of(shape));
  Mesh m = clean;
  m.V = noisy(clean, sigma, 11);
  const SegmentResult r = segment(m.V, m.F);
  expect_valid(m, r);
  const CutStats s = cut_stats(clean, r.labels);
  std::printf(
      "[segment] %-8s sigma %.1f: %d faces, %d segments (multicut %d, expected %d), %d cut edges, "
      "%.1f%% on creases\n",
      shape.c_str(), sigma, static_cast<int>(m.F.rows()), r.count, r.multicut_count, shape_patch_count(shape), s.cut,
      100 * s.fraction());
  EXPECT_LE(r.count, shape_patch_count(shape));
  EXPECT_GE(r.count, shape_patch_count(shape) - allowed_missing(shape, sigma));
  EXPECT_GE(s.fraction(), 0.9);
}

INSTANTIATE_TEST_SUITE_P(Segment, SegmentShapes,
                         ::testing::Combine(::testing::Values("cube", "cylinder", "fandisk"),
                                            ::testing::Values(0.0, 0.1, 0.2, 0.3)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_sigma" +
                                  std::to_string(static_cast<int>(std::lround(10 * std::get<1>(info.param))));
                         });

TEST(Segment, NoiseSeedsGiveStableCounts) {
  // The count does not hinge on one lucky seed.
  const Mesh clean = make_shape("cube", 10);
  for (std::uint64_t seed : {1, 2, 3}) {
    const SegmentResult r = segment(noisy(clean, 0.3, seed), clean.F);
    EXPECT_EQ(r.count, 6) << "seed " << seed;
  }
}

TEST(Segment, SmoothSphereIsOneSegment) {
  // 5,120 faces (3.8° between neighbours). On a much coarser sphere (1,280 faces, 7.5°) the
  // cad preset's piecewise-constant normals staircase into facets more than 15° apart and
  // the sphere splits into 21 parts; that is the normal filter's doing, not the multicut's.
  const Mesh m = make_shape("sphere", 20);
  const SegmentResult r = segment(m.V, m.F);
  expect_valid(m, r);
  EXPECT_EQ(r.count, 1);
  EXPECT_EQ(r.objective, 0.0);
}

TEST(Segment, ObjectiveAndProbabilitiesFollowTheConvention) {
  const Mesh m = make_shape("cube", 6);
  SegmentOptions o;
  o.min_area_fraction = 0;  // the multicut labels as they are
  const SegmentResult r = segment(m.V, m.F, o);
  EXPECT_EQ(r.count, r.multicut_count);
  EXPECT_NEAR(r.objective, r.multicut_report.objective, 1e-9);
  EXPECT_LT(r.objective, 0.0);  // cutting along the creases pays
  const Topology t = build_topology(m.F, m.V.rows());
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    ASSERT_TRUE(t.edge_is_interior[e]);
    EXPECT_GE(r.split_probability(e), o.clamp_probability);
    EXPECT_LE(r.split_probability(e), 1 - o.clamp_probability);
    const Eigen::RowVector3d n0 = r.normals.row(t.edge_faces(e, 0)), n1 = r.normals.row(t.edge_faces(e, 1));
    const double angle = std::acos(std::clamp(n0.dot(n1) / (n0.norm() * n1.norm()), -1.0, 1.0));
    if (angle < 14.9 * M_PI / 180) {
      EXPECT_EQ(r.split_probability(e), o.clamp_probability);
    }
  }
}

TEST(Segment, InvariantUnderScaleRotationTranslation) {
  const Mesh clean = make_shape("fandisk", 5);
  const Eigen::MatrixXd X0 = noisy(clean, 0.2, 5);
  const SegmentResult a = segment(X0, clean.F);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::MatrixXd X1 = ((250.0 * X0 * R.transpose()).rowwise() + Eigen::RowVector3d(7, -300, 12)).eval();
  const SegmentResult b = segment(X1, clean.F);
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(rand_index(a.labels, b.labels), 1.0);
}

TEST(Segment, SmallSegmentMergeIsOptional) {
  // With the merge off, the result is exactly the multicut's; with it on, no segment is below
  // the threshold.
  const Mesh clean = make_shape("cube", 10);
  const Eigen::MatrixXd X = noisy(clean, 0.3, 11);
  SegmentOptions off;
  off.min_area_fraction = 0;
  const SegmentResult a = segment(X, clean.F, off);
  EXPECT_EQ(a.count, a.multicut_count);
  SegmentOptions on;
  on.min_area_fraction = 0.05;
  const SegmentResult b = segment(X, clean.F, on);
  EXPECT_LE(b.count, a.count);
  for (int i = 0; i < b.count; ++i) EXPECT_GE(b.areas(i), 0.05 * b.areas.sum());
}

TEST(Segment, SegmentWithFieldReproducesSegment) {
  const Mesh m = make_shape("cylinder", 10);
  const SegmentResult a = segment(m.V, m.F);
  const SegmentResult b = segment_with_field(m.V, m.F, a.normals, a.v);
  EXPECT_TRUE(a.labels == b.labels);
}

TEST(Segment, RejectsBadOptionsAndInput) {
  const Mesh m = make_shape("cube", 3);
  SegmentOptions o;
  o.smooth_angle_deg = 0;
  try {
    segment(m.V, m.F, o);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("angle = 0"), std::string::npos);
  }
  o = SegmentOptions();
  o.clamp_probability = 0.5;
  EXPECT_THROW(segment(m.V, m.F, o), InvalidInput);
  o = SegmentOptions();
  o.min_area_fraction = 1;
  EXPECT_THROW(segment(m.V, m.F, o), InvalidInput);
  o = SegmentOptions();
  o.normals.alpha = -1;
  EXPECT_THROW(segment(m.V, m.F, o), InvalidInput);
  EXPECT_THROW(segment_with_field(m.V, m.F, Eigen::MatrixXd::Zero(2, 3), Eigen::VectorXd()), InvalidInput);
}

TEST(Segment, ProgressCanCancel) {
  const Mesh m = make_shape("cube", 4);
  EXPECT_THROW(segment(m.V, m.F, {}, [](const ProgressEvent&) { return false; }), Cancelled);
}

// ---- Rand index ----------------------------------------------------------------------------

TEST(Segment, RandIndexOfKnownLabellings) {
  Eigen::VectorXi a(6), b(6), c(6);
  a << 0, 0, 0, 1, 1, 1;
  b << 5, 5, 5, 2, 2, 2;  // same partition, other names
  c << 0, 0, 1, 1, 2, 2;
  EXPECT_EQ(rand_index(a, b), 1.0);
  // Pairs (15): together in a: 6; in c: 3, of which together in a too: (0,1), (4,5) = 2.
  // Agreements = both together 2 + both apart (15 − 6 − 3 + 2) = 8 → 10/15.
  EXPECT_NEAR(rand_index(a, c), 10.0 / 15.0, 1e-15);
  EXPECT_NEAR(rand_index(c, a), 10.0 / 15.0, 1e-15);
  // The sparse contingency table (many labels) agrees with the dense one.
  Eigen::VectorXi big_a(3000), big_b(3000);
  for (int i = 0; i < 3000; ++i) {
    big_a(i) = i;          // 3000 singletons
    big_b(i) = i / 2 * 7;  // pairs, labels up to ~10500
  }
  EXPECT_NEAR(rand_index(big_a, big_b), 1.0 - 1500.0 / (3000.0 * 2999 / 2), 1e-15);
  EXPECT_THROW(rand_index(a, Eigen::VectorXi::Zero(5)), InvalidInput);
}

// ---- feature lines ---------------------------------------------------------------------------

TEST(Feature, CubeHasTwelveCreaseChains) {
  const Mesh m = make_shape("cube", 8);
  const SegmentResult r = segment(m.V, m.F);
  const auto lines = feature_lines(m.V, m.F, r.v_normalized, 0.5);
  ASSERT_EQ(lines.size(), 12u);
  const Topology t = build_topology(m.F, m.V.rows());
  const Eigen::VectorXd dihedral = dihedral_angles(m.V, m.F, t);
  std::set<std::pair<int, int>> crease, covered;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (dihedral(e) > M_PI / 4) crease.insert({t.edges(e, 0), t.edges(e, 1)});
  for (const auto& l : lines) {
    EXPECT_EQ(l.size(), 9u);  // 8 edges along each cube edge at resolution 8
    for (size_t k = 0; k + 1 < l.size(); ++k) covered.insert({std::min(l[k], l[k + 1]), std::max(l[k], l[k + 1])});
  }
  EXPECT_EQ(covered, crease);
}

TEST(Feature, CylinderRimsAreClosedLoops) {
  const Mesh m = make_shape("cylinder", 10);
  const SegmentResult r = segment(m.V, m.F);
  const auto lines = feature_lines(m.V, m.F, r.v_normalized, 0.5);
  ASSERT_EQ(lines.size(), 2u);
  for (const auto& l : lines) {
    EXPECT_EQ(l.front(), l.back());
    EXPECT_EQ(l.size(), 32u);  // 31 segments around
  }
}

TEST(Feature, NoisyCubeLinesWithMinimumLength) {
  const Mesh clean = make_shape("cube", 10);
  const SegmentResult r = segment(noisy(clean, 0.2, 4), clean.F);
  const auto lines = feature_lines(clean.V, clean.F, r.v, 0.5, 3);
  EXPECT_GE(lines.size(), 12u);
  for (const auto& l : lines) EXPECT_GE(l.size(), 4u);
  EXPECT_THROW(feature_lines(clean.V, clean.F, r.v, 0.0), InvalidInput);
  EXPECT_THROW(feature_lines(clean.V, clean.F, Eigen::VectorXd::Ones(3), 0.5), InvalidInput);
}

// ---- public CAD meshes: clean against noisy ------------------------------------------------

namespace {

double clean_vs_noisy_rand_index(const std::string& clean_path, const std::string& noisy_path, int* counts) {
  const Mesh clean = read_mesh(clean_path), noisy_mesh = read_mesh(noisy_path);
  EXPECT_TRUE(clean.F == noisy_mesh.F) << "the pair must share its connectivity";
  const SegmentResult a = segment(clean.V, clean.F), b = segment(noisy_mesh.V, noisy_mesh.F);
  counts[0] = a.count;
  counts[1] = b.count;
  const CutStats s = cut_stats(clean, b.labels);
  const double ri = rand_index(a.labels, b.labels);
  std::printf("[segment] %s: clean %d segments, noisy %d segments, Rand index %.4f, noisy cuts on creases %.1f%%\n",
              noisy_path.c_str(), a.count, b.count, ri, 100 * s.fraction());
  return ri;
}

}  // namespace

TEST(Segment, PublicFandiskCleanVsNoisy) {
  MSMESH_REQUIRE_SHARED(clean, "gnf_zhang2015/fandisk/clean.obj");
  MSMESH_REQUIRE_SHARED(noisy_path, "gnf_zhang2015/fandisk/noisy_0.3.obj");
  int counts[2];
  const double ri = clean_vs_noisy_rand_index(clean, noisy_path, counts);
  RecordProperty("rand_index", std::to_string(ri));
  EXPECT_GE(ri, 0.95);
}

TEST(Segment, PublicBlockCleanVsNoisy) {
  MSMESH_REQUIRE_SHARED(clean, "gnf_zhang2015/block/clean.obj");
  MSMESH_REQUIRE_SHARED(noisy_path, "gnf_zhang2015/block/noisy_0.4.obj");
  int counts[2];
  const double ri = clean_vs_noisy_rand_index(clean, noisy_path, counts);
  RecordProperty("rand_index", std::to_string(ri));
  EXPECT_GE(ri, 0.95);
}
