// Writing meshes (msmesh/write_mesh.h): round trips through every format, attributes and
// face colours, refused meshes, no partial or temporary files left behind.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/read_mesh.h"
#include "msmesh/write_mesh.h"
#include "msmesh/write_polylines.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::TempDir;
namespace fs = std::filesystem;

namespace {

/// A grid with coordinates that need all 17 significant digits.
Mesh awkward_mesh() {
  Mesh m = test::grid(4, 0.3);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (Eigen::Index i = 0; i < m.V.size(); ++i) m.V(i) = m.V(i) * 1.2345678901234567 + u(gen) + 1.0 / 3.0;
  return m;
}

}  // namespace

// ---- round trips --------------------------------------------------------------------------------

TEST(IoRoundTrip, EveryFormatKeepsVerticesAndFaces) {
  TempDir dir;
  const Mesh m = awkward_mesh();
  struct Case {
    std::string name;
    bool binary;
  };
  for (const Case& c :
       {Case{"m.obj", false}, Case{"m.off", false}, Case{"ascii.ply", false}, Case{"binary.ply", true}}) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.file(c.name);
    write_mesh(path, m, WriteOptions{c.binary});
    Eigen::Index dropped = -1;
    const Mesh r = read_mesh(path, &dropped);
    EXPECT_EQ(dropped, 0);
    ASSERT_EQ(r.V.rows(), m.V.rows());
    ASSERT_EQ(r.F.rows(), m.F.rows());
    EXPECT_LE((r.V - m.V).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_TRUE(r.F == m.F);
  }
  // STL stores float32 corners per face; the reader welds equal positions back together.
  for (const Case& c : {Case{"ascii.stl", false}, Case{"binary.stl", true}}) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.file(c.name);
    write_mesh(path, m, WriteOptions{c.binary});
    const Mesh r = read_mesh(path);
    ASSERT_EQ(r.V.rows(), m.V.rows());
    ASSERT_EQ(r.F.rows(), m.F.rows());
    const double tol = c.binary ? 4 * std::numeric_limits<float>::epsilon() * m.V.cwiseAbs().maxCoeff() : 1e-12;
    for (Eigen::Index f = 0; f < m.F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        EXPECT_LE((r.V.row(r.F(f, k)) - m.V.row(m.F(f, k))).cwiseAbs().maxCoeff(), tol) << "face " << f;
  }
}

TEST(IoRoundTrip, VertexColoursThroughPlyAndOff) {
  TempDir dir;
  Mesh m = test::tetrahedron();
  m.vertex_colors.resize(4, 3);
  m.vertex_colors << 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.4, 0.6;
  for (const std::string name : {"c.ply", "c.off"}) {
    SCOPED_TRACE(name);
    write_mesh(dir.file(name), m);
    const Mesh r = read_mesh(dir.file(name));
    ASSERT_EQ(r.vertex_colors.rows(), 4);
    EXPECT_LE((r.vertex_colors - m.vertex_colors).cwiseAbs().maxCoeff(), 0.5 / 255 + 1e-12);
  }
}

// ---- writing ------------------------------------------------------------------------------------

TEST(IoWrite, FailedWriteLeavesNoFile) {
  TempDir dir;
  const std::string path = dir.file("missing_folder/out.ply");
  EXPECT_THROW(write_mesh(path, test::tetrahedron()), IoError);
  EXPECT_FALSE(fs::exists(path));
  try {
    write_mesh(path, test::tetrahedron());
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(write_mesh(dir.file("out.xyz"), test::tetrahedron()), IoError);
  EXPECT_TRUE(dir.listing().empty());
}

TEST(IoWrite, InvalidMeshIsRefusedBeforeTouchingTheFile) {
  TempDir dir;
  Mesh m = test::tetrahedron();
  m.F(0, 0) = 9;
  EXPECT_THROW(write_mesh(dir.file("bad.obj"), m), InvalidInput);
  m = test::tetrahedron();
  m.V(1, 1) = std::nan("");
  EXPECT_THROW(write_mesh(dir.file("bad.obj"), m), InvalidInput);
  EXPECT_TRUE(dir.listing().empty());
}

TEST(IoWrite, NoTemporaryFilesAreLeftBehind) {
  TempDir dir;
  const Mesh m = test::grid(3);
  for (const std::string name : {"a.obj", "a.off", "a.ply", "a.stl"}) write_mesh(dir.file(name), m);
  write_text_file(dir.file("notes.txt"), "hello\n");
  write_ply_face_colors(dir.file("colors.ply"), m, Eigen::MatrixXd::Constant(m.F.rows(), 3, 0.5));
  write_polylines(dir.file("lines.obj"), m.V, {{0, 1, 2}});
  // Overwriting an existing file goes through a temporary too.
  write_mesh(dir.file("a.obj"), test::tetrahedron());
  EXPECT_EQ(read_mesh(dir.file("a.obj")).F.rows(), 4);
  const std::vector<std::string> expected = {"a.obj",      "a.off",     "a.ply",    "a.stl",
                                             "colors.ply", "lines.obj", "notes.txt"};
  EXPECT_EQ(dir.listing(), expected);
}

TEST(IoWrite, FaceColoursPly) {
  TempDir dir;
  const Mesh m = test::tetrahedron();
  Eigen::MatrixXd C(4, 3);
  C << 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0.5, 0.5;
  for (bool binary : {true, false}) {
    const std::string path = dir.file(binary ? "b.ply" : "a.ply");
    write_ply_face_colors(path, m, C, binary);
    const std::string bytes = read_bytes(path);
    EXPECT_NE(bytes.find("element face 4\nproperty list uchar int vertex_indices\nproperty uchar red\n"),
              std::string::npos);
    if (!binary) EXPECT_NE(bytes.find("3 1 3 2 128 128 128\n"), std::string::npos);
    const Mesh r = read_mesh(path);
    EXPECT_TRUE(r.F == m.F);
  }
  EXPECT_THROW(write_ply_face_colors(dir.file("c.ply"), m, Eigen::MatrixXd::Zero(3, 3)), InvalidInput);
}

// ---- public meshes ------------------------------------------------------------------------------

TEST(IoShared, SameMeshThroughEveryFormat) {
  MSMESH_REQUIRE_SHARED(path, "gnf_zhang2015/fandisk/clean.obj");
  TempDir dir;
  const Mesh m = read_mesh(path);
  EXPECT_EQ(m.V.rows(), 6475);
  EXPECT_EQ(m.F.rows(), 12946);
  for (const std::string name : {"f.off", "f.ply", "f_ascii.ply", "f.obj"}) {
    SCOPED_TRACE(name);
    write_mesh(dir.file(name), m, WriteOptions{name != "f_ascii.ply"});
    const Mesh r = read_mesh(dir.file(name));
    ASSERT_EQ(r.V.rows(), m.V.rows());
    EXPECT_EQ((r.V - m.V).cwiseAbs().maxCoeff(), 0.0);  // shortest round-trip digits are exact
    EXPECT_TRUE(r.F == m.F);
  }
  write_mesh(dir.file("f.stl"), m);
  const Mesh s = read_mesh(dir.file("f.stl"));
  EXPECT_EQ(s.V.rows(), m.V.rows());
  ASSERT_EQ(s.F.rows(), m.F.rows());
  double worst = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, (s.V.row(s.F(f, k)) - m.V.row(m.F(f, k))).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, 1e-6 * m.V.cwiseAbs().maxCoeff());
}

TEST(IoShared, AsciiAndBinaryPlyOfTheBunnyAgree) {
  MSMESH_REQUIRE_SHARED(path, "stanford_bunny_ply/bunny/bun_zipper.ply");
  TempDir dir;
  const Mesh m = read_mesh(path);
  write_mesh(dir.file("bunny.ply"), m, WriteOptions{true});
  const Mesh b = read_mesh(dir.file("bunny.ply"));
  EXPECT_TRUE(b.V == m.V);
  EXPECT_TRUE(b.F == m.F);
}

// Colours, uv and normals through each format (docs/robustness.md, "Nothing lost"); through
// `msmesh denoise`: cli/test_nothing_lost_cli.cpp.
TEST(NothingLost, AttributesRoundTripThroughEachFormat) {
  TempDir d;
  const Mesh m = test::attributed_grid();
  for (const std::string name : {"a.ply", "b.obj"}) {
    write_mesh(d.file(name), m);
    const Mesh r = read_mesh(d.file(name));
    SCOPED_TRACE(name);
    EXPECT_EQ(r.vertex_colors.rows(), m.V.rows());
    EXPECT_EQ(r.uv.rows(), m.V.rows());
    EXPECT_EQ(r.vertex_normals.rows(), m.V.rows());
    EXPECT_LT((r.uv - m.uv).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((r.vertex_normals - m.vertex_normals).cwiseAbs().maxCoeff(), 1e-12);
  }
  WriteOptions ascii;
  ascii.binary = false;
  write_mesh(d.file("c.ply"), m, ascii);
  const Mesh r = read_mesh(d.file("c.ply"));
  EXPECT_LT((r.uv - m.uv).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((r.vertex_colors - m.vertex_colors).cwiseAbs().maxCoeff(), 1e-9);
}
