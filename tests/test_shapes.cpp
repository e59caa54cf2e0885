// Procedural shapes (shapes.h): every named shape at two resolutions is a valid, watertight,
// manifold, outward-oriented mesh without degenerate or sliver faces, whose crease-separated
// patches are exactly shape_patch_count(name); plus per-shape sizes and properties.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <set>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

constexpr double kPi = 3.14159265358979323846;
/// Edges whose faces' normals differ by less than this join one smooth patch.
constexpr double kCreaseAngle = 20 * kPi / 180;

/// Signed volume enclosed by F (#F by 3); positive for outward-oriented closed meshes.
double signed_volume(const Mesh& m) {
  double v = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    v += a.dot(b.cross(c)) / 6;
  }
  return v;
}

/// Smallest interior angle of any face, in degrees.
double min_angle_degrees(const Mesh& m) {
  double smallest = 180;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = m.V.row(m.F(f, k));
      const Eigen::Vector3d a = Eigen::Vector3d(m.V.row(m.F(f, (k + 1) % 3))) - p;
      const Eigen::Vector3d b = Eigen::Vector3d(m.V.row(m.F(f, (k + 2) % 3))) - p;
      smallest = std::min(smallest, std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / kPi);
    }
  return smallest;
}

/// Number of face regions connected across edges with dihedral angle below kCreaseAngle.
int crease_patch_count(const Mesh& m) {
  const Topology t = build_topology(m.F, m.V.rows());
  const Eigen::VectorXd angle = dihedral_angles(m.V, m.F, t);
  std::vector<int> parent(static_cast<size_t>(m.F.rows()));
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (t.edge_is_interior[e] && angle(e) < kCreaseAngle) parent[find(t.edge_faces(e, 0))] = find(t.edge_faces(e, 1));
  int count = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) count += find(static_cast<int>(f)) == f ? 1 : 0;
  return count;
}

/// The resolutions every named shape is checked at.
const int kResolutions[] = {8, 16};

/// Expected minimum face angle (degrees): structured meshes are near-regular, the patch-meshed
/// CAD part is Delaunay on a lattice, the pyramid is deliberately irregular.
double min_angle_bound(const std::string& name) {
  if (name == "pyramid") return 10;
  return 15;
}

}  // namespace

TEST(Shapes, NamesAndPatchCounts) {
  const std::vector<std::string> names = shape_names();
  EXPECT_EQ(names.size(), 7u);
  for (const char* expected : {"cube", "cylinder", "sphere", "torus", "fandisk", "pyramid", "holes"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  EXPECT_EQ(shape_patch_count("cube"), 6);
  EXPECT_EQ(shape_patch_count("cylinder"), 3);
  EXPECT_EQ(shape_patch_count("sphere"), 1);
  EXPECT_EQ(shape_patch_count("torus"), 1);
  EXPECT_EQ(shape_patch_count("pyramid"), 5);
  EXPECT_EQ(shape_patch_count("holes"), 6);
  EXPECT_EQ(shape_patch_count("fandisk"), fandisk_like_patch_count());
}

TEST(Shapes, UnknownNameListsValidNames) {
  try {
    make_shape("teapot", 8);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("teapot"), std::string::npos) << what;
    for (const std::string& name : shape_names()) EXPECT_NE(what.find(name), std::string::npos) << what;
  }
  EXPECT_THROW(shape_patch_count("teapot"), InvalidInput);
  EXPECT_THROW(make_shape("cube", 0), InvalidInput);
}

TEST(Shapes, InvalidParametersThrow) {
  EXPECT_THROW(make_cube(0), InvalidInput);
  EXPECT_THROW(make_cylinder(2, 4), InvalidInput);
  EXPECT_THROW(make_cylinder(8, 0), InvalidInput);
  EXPECT_THROW(make_sphere(-1), InvalidInput);
  EXPECT_THROW(make_torus(2, 8), InvalidInput);
  EXPECT_THROW(make_fandisk_like(0), InvalidInput);
  EXPECT_THROW(make_pyramid(0), InvalidInput);
  EXPECT_THROW(make_cube_with_holes(3, 1), InvalidInput);
  EXPECT_THROW(make_cube_with_holes(8, 27), InvalidInput);
}

// The property every named shape has at every resolution.
TEST(Shapes, EveryShapeIsValidWatertightAndOriented) {
  for (const std::string& name : shape_names()) {
    for (int r : kResolutions) {
      SCOPED_TRACE(name + " at resolution " + std::to_string(r));
      const Mesh m = make_shape(name, r);
      ASSERT_NO_THROW(validate_mesh(m.V, m.F, name));
      ASSERT_GT(m.F.rows(), 0);
      const bool closed = name != "holes";
      const Topology t = build_topology(m.F, m.V.rows());
      const TopologySummary s = summarize_topology(m.F, t);
      EXPECT_EQ(s.boundary_edges == 0, closed);
      EXPECT_EQ(s.non_manifold_edges, 0);
      EXPECT_EQ(s.non_manifold_vertices, 0);
      EXPECT_EQ(s.inconsistently_oriented_edges, 0);
      EXPECT_EQ(s.unreferenced_vertices, 0);
      EXPECT_EQ(s.components, 1);
      const Eigen::Index euler = m.V.rows() - t.num_edges() + m.F.rows();
      // A torus has genus 1; make_shape("holes") removes 2 disks from a sphere-like cube.
      EXPECT_EQ(euler, name == "torus" || name == "holes" ? 0 : 2);
      if (closed) {
        EXPECT_GT(signed_volume(m), 0);
      }
      EXPECT_GT(face_areas(m.V, m.F).minCoeff(), 1e-12);
      EXPECT_GT(min_angle_degrees(m), min_angle_bound(name));
      EXPECT_EQ(crease_patch_count(m), shape_patch_count(name));
    }
  }
}

TEST(Shapes, SizesGrowWithResolution) {
  for (const std::string& name : shape_names()) {
    SCOPED_TRACE(name);
    const Eigen::Index coarse = make_shape(name, 8).F.rows(), fine = make_shape(name, 16).F.rows();
    EXPECT_GT(fine, 2 * coarse);
  }
  const Eigen::Index fandisk = make_shape("fandisk", 24).F.rows();
  EXPECT_GT(fandisk, 5000);
  EXPECT_LT(fandisk, 20000);
}

TEST(Shapes, CubeCountsAndVerticesOnSurface) {
  for (int n = 1; n <= 6; ++n) {
    const Mesh m = make_cube(n);
    EXPECT_EQ(m.F.rows(), 12 * n * n);
    EXPECT_EQ(m.V.rows(), 6 * n * n + 2);  // Euler: no vertex duplicated along the edges
    EXPECT_NEAR(signed_volume(m), 8.0, 1e-12);
    for (Eigen::Index v = 0; v < m.V.rows(); ++v) EXPECT_NEAR(m.V.row(v).cwiseAbs().maxCoeff(), 1.0, 1e-15);
  }
  EXPECT_EQ(crease_patch_count(make_cube(1)), 6);
}

TEST(Shapes, CylinderCapsAndOpenTube) {
  const Mesh closed = make_cylinder(24, 6);
  const TopologySummary sc = summarize_topology(closed.F, build_topology(closed.F, closed.V.rows()));
  EXPECT_EQ(sc.boundary_edges, 0);
  EXPECT_EQ(crease_patch_count(closed), 3);
  EXPECT_GT(min_angle_degrees(closed), 25);
  EXPECT_NEAR(signed_volume(closed), 2 * 24 * std::sin(2 * kPi / 24) / 2, 1e-9);  // inscribed prism

  const Mesh open = make_cylinder(24, 6, false);
  EXPECT_EQ(open.F.rows(), 2 * 24 * 6);
  const TopologySummary so = summarize_topology(open.F, build_topology(open.F, open.V.rows()));
  EXPECT_EQ(so.boundary_loops.size(), 2u);
  EXPECT_EQ(so.boundary_edges, 48);
  EXPECT_EQ(so.non_manifold_vertices, 0);
  EXPECT_EQ(so.inconsistently_oriented_edges, 0);
  // The caps meet the side only at the rim: every rim vertex of the open tube is in the closed mesh.
  EXPECT_EQ(closed.V.topRows(open.V.rows()), open.V);
}

TEST(Shapes, SphereAndTorusCounts) {
  for (int s = 0; s <= 3; ++s) {
    const Mesh m = make_sphere(s);
    EXPECT_EQ(m.F.rows(), 20 * (1 << (2 * s)));
    EXPECT_GT(signed_volume(m), 0);
    EXPECT_NEAR(m.V.rowwise().norm().maxCoeff(), 1.0, 1e-12);
    EXPECT_NEAR(m.V.rowwise().norm().minCoeff(), 1.0, 1e-12);
  }
  const Mesh torus = make_torus(30, 12);
  EXPECT_EQ(torus.F.rows(), 2 * 30 * 12);
  EXPECT_EQ(torus.V.rows(), 30 * 12);
  EXPECT_GT(signed_volume(torus), 0);
}

TEST(Shapes, FandiskHasSharpAndSmoothFeatures) {
  const Mesh m = make_fandisk_like(16);
  const Topology t = build_topology(m.F, m.V.rows());
  const Eigen::VectorXd angle = dihedral_angles(m.V, m.F, t);
  // Crease angles in degrees that must occur (±2°): 30° and 45° (profile), 90°, 115° concave.
  for (double crease : {30.0, 45.0, 90.0, 115.0}) {
    bool found = false;
    for (Eigen::Index e = 0; e < angle.size(); ++e) found |= std::abs(angle(e) * 180 / kPi - crease) < 2;
    EXPECT_TRUE(found) << crease;
  }
  // Between 20° and the shallowest crease there is a gap: no ambiguous edges.
  for (Eigen::Index e = 0; e < angle.size(); ++e) {
    const double deg = angle(e) * 180 / kPi;
    EXPECT_TRUE(deg < 12 || deg > 28) << "edge " << e << " at " << deg << "°";
  }
  // The part spans [-1,1] along its longest axis and is centred.
  const Eigen::RowVector3d lo = m.V.colwise().minCoeff(), hi = m.V.colwise().maxCoeff();
  EXPECT_NEAR((hi - lo).maxCoeff(), 2.0, 1e-12);
  EXPECT_LT((hi + lo).norm(), 1e-12);
}

TEST(Shapes, PyramidIsDeterministicIrregularAndGraded) {
  const Mesh a = make_pyramid(12, 7), b = make_pyramid(12, 7), c = make_pyramid(12, 8);
  EXPECT_EQ(a.V, b.V);
  EXPECT_EQ(a.F, b.F);
  EXPECT_TRUE(a.V.rows() != c.V.rows() || a.V != c.V);
  EXPECT_EQ(crease_patch_count(c), 5);
  // Finer on the -x side: edges there are shorter on average.
  const Topology t = build_topology(a.F, a.V.rows());
  const Eigen::VectorXd len = edge_lengths(a.V, t);
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    const double x = 0.5 * (a.V(t.edges(e, 0), 0) + a.V(t.edges(e, 1), 0));
    if (std::abs(x) < 0.5) continue;
    sum[x > 0] += len(e);
    ++count[x > 0];
  }
  EXPECT_LT(sum[0] / count[0], 0.75 * sum[1] / count[1]);
  // Irregular: edge lengths vary well beyond the grading.
  Eigen::VectorXd rel(t.num_edges());
  const double h = 2.0 / 12;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    const double x = 0.5 * (a.V(t.edges(e, 0), 0) + a.V(t.edges(e, 1), 0));
    rel(e) = len(e) / (h * (0.4 + 0.3 * (x + 1)));
  }
  const double mean = rel.mean();
  const double sd = std::sqrt((rel.array() - mean).square().mean());
  EXPECT_GT(sd / mean, 0.1);
}

TEST(Shapes, HolesAreSimpleLoops) {
  for (int n : {4, 5, 8, 13}) {
    for (int holes = 0; holes <= (n == 4 ? 4 : 26); ++holes) {
      SCOPED_TRACE("n " + std::to_string(n) + ", holes " + std::to_string(holes));
      const Mesh m = make_cube_with_holes(n, holes);
      const Topology t = build_topology(m.F, m.V.rows());
      const TopologySummary s = summarize_topology(m.F, t);
      ASSERT_EQ(static_cast<int>(s.boundary_loops.size()), holes);
      EXPECT_EQ(s.non_manifold_vertices, 0);
      EXPECT_EQ(s.non_manifold_edges, 0);
      EXPECT_EQ(s.unreferenced_vertices, 0);
      EXPECT_EQ(s.inconsistently_oriented_edges, 0);
      EXPECT_EQ(s.components, 1);
      // Every boundary vertex lies on exactly one loop, once.
      size_t loop_vertices = 0;
      std::set<int> seen;
      for (const auto& loop : s.boundary_loops) {
        loop_vertices += loop.size();
        seen.insert(loop.begin(), loop.end());
      }
      EXPECT_EQ(loop_vertices, seen.size());
      EXPECT_EQ(static_cast<Eigen::Index>(loop_vertices), s.boundary_edges);
      EXPECT_EQ(m.V.rows() - t.num_edges() + m.F.rows(), 2 - holes);
    }
  }
  EXPECT_THROW(make_cube_with_holes(4, 5), InvalidInput);  // neighbouring holes would merge

  // The first hole crosses the cube edge x = z = 1; the second is centred on the face x = -1.
  const Mesh m = make_cube_with_holes(12, 2);
  const TopologySummary s = summarize_topology(m.F, build_topology(m.F, m.V.rows()));
  ASSERT_EQ(s.boundary_loops.size(), 2u);
  bool across_edge = false, on_face = false;
  for (const auto& loop : s.boundary_loops) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : loop) c += m.V.row(v).transpose();
    c /= static_cast<double>(loop.size());
    across_edge |= (c - Eigen::Vector3d(1, 0, 1)).norm() < 0.3 && c.x() < 1 - 1e-9 && c.z() < 1 - 1e-9;
    on_face |= (c - Eigen::Vector3d(-1, 0, 0)).norm() < 1e-9;
  }
  EXPECT_TRUE(across_edge);
  EXPECT_TRUE(on_face);
  EXPECT_EQ(crease_patch_count(m), 6);
}
