// mesh_statistics.h: area, volume of closed components, watertightness, Euler characteristic,
// boundary loops and genus, on shapes whose figures are known.
#include <gtest/gtest.h>

#include <cmath>

#include "msmesh/errors.h"
#include "msmesh/mesh_statistics.h"
#include "msmesh/shapes.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

/// A Moebius strip: `n` quads around a circle, the strip turning half a turn.
Mesh moebius(int n) {
  Mesh m;
  m.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n, half = t / 2;
    for (int s = 0; s < 2; ++s) {
      const double w = s == 0 ? -0.3 : 0.3;
      m.V.row(2 * i + s) << (1 + w * std::cos(half)) * std::cos(t), (1 + w * std::cos(half)) * std::sin(t),
          w * std::sin(half);
    }
  }
  m.F.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    // After a full turn the strip comes back upside down: the last quad joins crosswise.
    const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    m.F.row(2 * i) << a, c, b;
    m.F.row(2 * i + 1) << b, c, d;
  }
  return m;
}

}  // namespace

TEST(MeshStatistics, CubeAreaVolumeAndGenus) {
  const Mesh cube = make_cube(3);  // [-1,1]^3
  const MeshStatistics s = mesh_statistics(cube.V, cube.F);
  EXPECT_NEAR(s.area, 24.0, 1e-9);
  EXPECT_NEAR(s.volume, 8.0, 1e-9);
  EXPECT_TRUE(s.watertight);
  EXPECT_EQ(s.components, 1);
  EXPECT_EQ(s.closed_components, 1);
  EXPECT_EQ(s.euler_characteristic, 2);
  EXPECT_EQ(s.boundary_loops, 0);
  EXPECT_EQ(s.genus, 0);
  ASSERT_EQ(s.per_component.size(), 1u);
  const ComponentStatistics& c = s.per_component[0];
  EXPECT_TRUE(c.closed && c.manifold && c.orientable && c.consistently_oriented);
  EXPECT_EQ(c.faces, cube.F.rows());
  EXPECT_EQ(c.vertices, cube.V.rows());
}

TEST(MeshStatistics, SphereApproachesFourPi) {
  const Mesh sphere = make_sphere(4);
  const MeshStatistics s = mesh_statistics(sphere.V, sphere.F);
  // An inscribed polyhedron: a little less than the sphere, within 0.5 %.
  EXPECT_LT(s.area, 4 * M_PI);
  EXPECT_GT(s.area, 4 * M_PI * 0.995);
  EXPECT_LT(s.volume, 4.0 / 3.0 * M_PI);
  EXPECT_GT(s.volume, 4.0 / 3.0 * M_PI * 0.99);
  EXPECT_EQ(s.genus, 0);
  EXPECT_TRUE(s.watertight);
}

TEST(MeshStatistics, TorusHasGenusOne) {
  const Mesh torus = make_torus(24, 12);
  const MeshStatistics s = mesh_statistics(torus.V, torus.F);
  EXPECT_EQ(s.euler_characteristic, 0);
  EXPECT_EQ(s.genus, 1);
  EXPECT_TRUE(s.watertight);
  // Volume of the torus: 2π² R r² = 2π²·1·0.16, approached from below by the polygons
  // (about 0.99 × 0.955 of it with 24 × 12 segments).
  const double exact = 2 * M_PI * M_PI * 0.16;
  EXPECT_LT(s.volume, exact);
  EXPECT_GT(s.volume, 0.92 * exact);
}

TEST(MeshStatistics, OpenDiskHasBoundaryAndNoVolume) {
  const Mesh disk = test::grid(4);  // the unit square, one boundary loop
  const MeshStatistics s = mesh_statistics(disk.V, disk.F);
  EXPECT_NEAR(s.area, 1.0, 1e-12);
  EXPECT_FALSE(s.watertight);
  EXPECT_EQ(s.closed_components, 0);
  EXPECT_EQ(s.volume, 0.0);
  EXPECT_EQ(s.euler_characteristic, 1);
  EXPECT_EQ(s.boundary_loops, 1);
  EXPECT_EQ(s.genus, 0);
  EXPECT_FALSE(s.per_component[0].closed);
}

TEST(MeshStatistics, InwardFacesGiveANegativeVolume) {
  Mesh cube = make_cube(2);
  cube.F.col(1).swap(cube.F.col(2));
  const MeshStatistics s = mesh_statistics(cube.V, cube.F);
  EXPECT_NEAR(s.volume, -8.0, 1e-9);
  EXPECT_TRUE(s.watertight) << "consistently oriented, only inwards";
}

TEST(MeshStatistics, MixedOrientationIsNotWatertightButHasAVolume) {
  Mesh cube = make_cube(2);
  std::swap(cube.F(0, 1), cube.F(0, 2));  // one face flipped
  const MeshStatistics s = mesh_statistics(cube.V, cube.F);
  EXPECT_FALSE(s.watertight);
  EXPECT_FALSE(s.per_component[0].consistently_oriented);
  EXPECT_TRUE(s.per_component[0].orientable);
  EXPECT_TRUE(s.per_component[0].closed);
  EXPECT_NEAR(s.volume, 8.0, 1e-9) << "the volume of the re-oriented surface";
  EXPECT_EQ(s.genus, 0);
}

TEST(MeshStatistics, ComponentsAddUp) {
  const Mesh cube = make_cube(2);
  const Mesh disk = test::grid(3);
  Mesh both;
  both.V.resize(cube.V.rows() + disk.V.rows(), 3);
  both.V << cube.V, disk.V.rowwise() + Eigen::RowVector3d(5, 0, 0);
  both.F.resize(cube.F.rows() + disk.F.rows(), 3);
  both.F << cube.F, disk.F.array() + static_cast<int>(cube.V.rows());
  const MeshStatistics s = mesh_statistics(both.V, both.F);
  EXPECT_EQ(s.components, 2);
  EXPECT_EQ(s.closed_components, 1);
  EXPECT_NEAR(s.area, 25.0, 1e-9);
  EXPECT_NEAR(s.volume, 8.0, 1e-9) << "the open disk adds no volume";
  EXPECT_EQ(s.euler_characteristic, 3);
  EXPECT_EQ(s.boundary_loops, 1);
  EXPECT_EQ(s.genus, 0);
  EXPECT_FALSE(s.watertight);
}

TEST(MeshStatistics, MoebiusStripIsNotOrientable) {
  const Mesh m = moebius(12);
  const MeshStatistics s = mesh_statistics(m.V, m.F);
  ASSERT_EQ(s.components, 1);
  EXPECT_FALSE(s.per_component[0].orientable);
  EXPECT_EQ(s.per_component[0].genus, -1);
  EXPECT_EQ(s.genus, -1);
  EXPECT_EQ(s.euler_characteristic, 0);
}

TEST(MeshStatistics, NonManifoldEdgeHasNoGenus) {
  const Mesh fin = test::fin();
  const MeshStatistics s = mesh_statistics(fin.V, fin.F);
  EXPECT_FALSE(s.per_component[0].manifold);
  EXPECT_EQ(s.genus, -1);
  EXPECT_FALSE(s.watertight);
}

TEST(MeshStatistics, EmptyAndInvalidMeshes) {
  const MeshStatistics s = mesh_statistics(Eigen::MatrixXd(0, 3), Eigen::MatrixXi(0, 3));
  EXPECT_EQ(s.components, 0);
  EXPECT_FALSE(s.watertight);
  EXPECT_EQ(s.genus, -1);
  Eigen::MatrixXi F(1, 3);
  F << 0, 1, 5;
  EXPECT_THROW(mesh_statistics(Eigen::MatrixXd::Zero(3, 3), F), InvalidInput);
}
