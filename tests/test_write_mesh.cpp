// Writing meshes (msmesh/write_mesh.h): round trips through every format, attributes and
// face colours, refused meshes, no partial or temporary files left behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/read_mesh.h"
#include "msmesh/threads.h"
#include "msmesh/write_mesh.h"
#include "msmesh/write_polylines.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;
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

TEST(IoRoundTrip, LargeObjIsTheSameBytesAtEveryThreadCountAndReadsBackExactly) {
  // 36K vertices and 72K faces: the vertex and face lines are formatted in parallel blocks of
  // 4096 lines, a batch of 16 at a time (the faces take two batches); the blocks must come out
  // whole and in order. Plain, with colours, and with float coordinates.
  TempDir dir;
  Mesh m = test::grid(190, 0.3);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  for (Eigen::Index i = 0; i < m.V.size(); ++i) m.V(i) = m.V(i) * 1.2345678901234567 + u(gen) + 1.0 / 3.0;
  ASSERT_GT(m.F.rows(), 16 * 4096);
  Mesh coloured = m;
  coloured.vertex_colors = (Eigen::MatrixXd::Random(m.V.rows(), 3).array() * 0.5 + 0.5).matrix();
  Mesh single = m;
  single.position_type = ScalarType::Float32;
  single.V = m.V.cast<float>().cast<double>();
  const int before = threads();
  for (const Mesh* mesh : {&m, &coloured, &single}) {
    std::string first;
    for (const int n : {1, 2, 3}) {
      SCOPED_TRACE(n);
      set_threads(n);
      const std::string path = dir.file("large" + std::to_string(n) + ".obj");
      write_mesh(path, *mesh);
      const std::string bytes = read_bytes(path);
      if (n == 1) first = bytes;
      EXPECT_TRUE(bytes == first);
      const Mesh r = read_mesh(path);
      // (float coordinates are written as the float's shortest digits: the same float back)
      if (mesh->position_type == ScalarType::Float32)
        EXPECT_TRUE(r.V.cast<float>() == mesh->V.cast<float>());
      else
        EXPECT_TRUE(r.V == mesh->V);
      EXPECT_TRUE(r.F == mesh->F);
      if (mesh->vertex_colors.size()) EXPECT_TRUE(r.vertex_colors == mesh->vertex_colors);
    }
  }
  set_threads(before);
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

// ---- attributes per format (docs/robustness.md, "Attributes") ------------------------------------

namespace {

/// A noisy 6×6 grid with every attribute: RGBA vertex colours and face colours (exact in 8
/// bits), per-corner texture coordinates with a seam down the middle, two materials, two
/// groups, an object, extra vertex properties of several types. The faces of the left half
/// come first (so that glTF, one primitive per group, keeps their order).
Mesh fully_attributed_grid() {
  Mesh m = test::noisy(test::grid(6, 0.2), 0.01);
  {
    std::vector<int> left, right;
    for (Eigen::Index f = 0; f < m.F.rows(); ++f)
      ((m.V(m.F(f, 0), 0) + m.V(m.F(f, 1), 0) + m.V(m.F(f, 2), 0)) / 3 < 0.5 ? left : right)
          .push_back(static_cast<int>(f));
    left.insert(left.end(), right.begin(), right.end());
    const Eigen::MatrixXi F = m.F;
    for (std::size_t k = 0; k < left.size(); ++k) m.F.row(static_cast<Eigen::Index>(k)) = F.row(left[k]);
  }
  const Eigen::Index nv = m.V.rows(), nf = m.F.rows();
  m.vertex_colors.resize(nv, 4);
  for (Eigen::Index i = 0; i < nv; ++i)
    m.vertex_colors.row(i) << (i % 7) * 40 / 255.0, (i % 5) * 60 / 255.0, (i % 3) * 120 / 255.0, (i % 2 ? 1.0 : 0.4);
  m.face_colors.resize(nf, 3);
  for (Eigen::Index f = 0; f < nf; ++f) m.face_colors.row(f) << (f % 4) * 80 / 255.0, 10 / 255.0, 1.0;
  // Two charts: faces left of x = 0.5 use texcoords of chart 0, the others of chart 1.
  m.texcoords.resize(2 * nv, 2);
  for (Eigen::Index i = 0; i < nv; ++i) {
    m.texcoords.row(i) << 0.5 * m.V(i, 0), m.V(i, 1);
    m.texcoords.row(nv + i) << 0.5 + 0.5 * m.V(i, 0), m.V(i, 1);
  }
  m.face_texcoords.resize(nf, 3);
  m.material_names = {"left", "right"};
  m.face_materials.resize(nf);
  m.group_names = {"chart0", "chart1"};
  m.face_groups.resize(nf);
  m.object_names = {"sheet"};
  m.face_objects = Eigen::VectorXi::Zero(nf);
  for (Eigen::Index f = 0; f < nf; ++f) {
    const double cx = (m.V(m.F(f, 0), 0) + m.V(m.F(f, 1), 0) + m.V(m.F(f, 2), 0)) / 3;
    const int chart = cx < 0.5 ? 0 : 1;
    for (int k = 0; k < 3; ++k) m.face_texcoords(f, k) = m.F(f, k) + chart * static_cast<int>(nv);
    m.face_materials(f) = chart;
    m.face_groups(f) = chart;
  }
  Eigen::VectorXd q(nv), s(nv), d(nv);
  for (Eigen::Index i = 0; i < nv; ++i) q(i) = i % 200, s(i) = -3.0 * static_cast<double>(i), d(i) = 0.1 * i;
  m.vertex_properties = {
      {"quality", q, ScalarType::UInt8}, {"label", s, ScalarType::Int16}, {"value", d, ScalarType::Float64}};
  return m;
}

/// The texture coordinates of every face corner (per-vertex or per-corner alike).
Eigen::MatrixXd corner_uv(const Mesh& m) {
  Eigen::MatrixXd c(m.F.rows() * 3, 2);
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int t = m.face_texcoords.size() ? m.face_texcoords(f, k) : m.F(f, k);
      c.row(3 * f + k) = m.face_texcoords.size() ? m.texcoords.row(t) : m.uv.row(t);
    }
  return c;
}

/// Largest difference of the texture coordinates of corresponding face corners of `a` and `b`
/// (same faces in the same order; glTF renumbers vertices, so corners are also checked to be
/// at the same position).
double corner_uv_error(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.F.rows(), b.F.rows());
  const Eigen::MatrixXd ca = corner_uv(a), cb = corner_uv(b);
  double worst = 0;
  for (Eigen::Index f = 0; f < a.F.rows() && f < b.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      EXPECT_LT((a.V.row(a.F(f, k)) - b.V.row(b.F(f, k))).norm(), 1e-6) << "face " << f;
      worst = std::max(worst, (ca.row(3 * f + k) - cb.row(3 * f + k)).cwiseAbs().maxCoeff());
    }
  return worst;
}

/// Largest difference of the vertex colours at corresponding face corners.
double corner_color_error(const Mesh& a, const Mesh& b) {
  double worst = 0;
  for (Eigen::Index f = 0; f < a.F.rows() && f < b.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, (a.vertex_colors.row(a.F(f, k)) - b.vertex_colors.row(b.F(f, k))).cwiseAbs().maxCoeff());
  return worst;
}

}  // namespace

TEST(Attributes, PlyKeepsFaceColoursAlphaExtraPropertiesAndCornerUv) {
  TempDir d;
  const Mesh m = fully_attributed_grid();
  for (const bool binary : {true, false}) {
    SCOPED_TRACE(binary ? "binary" : "ascii");
    const std::string path = d.file(binary ? "b.ply" : "a.ply");
    write_mesh(path, m, WriteOptions{binary});
    const Mesh r = read_mesh(path);
    EXPECT_TRUE(r.V == m.V);
    EXPECT_TRUE(r.F == m.F);
    EXPECT_LT((r.vertex_colors - m.vertex_colors).cwiseAbs().maxCoeff(), 1e-12);
    ASSERT_EQ(r.face_colors.rows(), m.F.rows());
    EXPECT_LT((r.face_colors - m.face_colors).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(corner_uv_error(m, r), 1e-15);
    ASSERT_EQ(r.vertex_properties.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(r.vertex_properties[k].name, m.vertex_properties[k].name);
      EXPECT_EQ(r.vertex_properties[k].type, m.vertex_properties[k].type);
      EXPECT_TRUE(r.vertex_properties[k].values == m.vertex_properties[k].values) << r.vertex_properties[k].name;
    }
    EXPECT_EQ(r.position_type, ScalarType::Float64);
    // What PLY cannot hold is named.
    const auto lost = unsupported_attributes(m, path);
    ASSERT_EQ(lost.size(), 3u);
    EXPECT_EQ(lost[0], "PLY cannot hold materials per face: not written");
  }
}

TEST(Attributes, PlyFloatStaysFloat) {
  TempDir d;
  write_bytes(d.file("f.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "property float intensity\nelement face 1\nproperty list uchar int vertex_indices\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\nend_header\n"
              "0.1 0 0 0.3\n1 0.2 0 1.5\n0 1 0.7 2\n3 0 1 2 255 0 10 128\n");
  const Mesh m = read_mesh(d.file("f.ply"));
  EXPECT_EQ(m.position_type, ScalarType::Float32);
  EXPECT_EQ(m.V(0, 0), static_cast<double>(0.1f));
  ASSERT_EQ(m.vertex_properties.size(), 1u);
  EXPECT_EQ(m.vertex_properties[0].type, ScalarType::Float32);
  ASSERT_EQ(m.face_colors.cols(), 4);
  EXPECT_NEAR(m.face_colors(0, 3), 128 / 255.0, 1e-15);
  write_mesh(d.file("g.ply"), m, WriteOptions{false});
  const std::string text = read_bytes(d.file("g.ply"));
  EXPECT_NE(text.find("property float x\n"), std::string::npos) << text;
  EXPECT_NE(text.find("property float intensity\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n0.1 0 0 0.3\n"), std::string::npos) << text;  // the same digits as the source
  write_mesh(d.file("g.obj"), m);
  EXPECT_NE(read_bytes(d.file("g.obj")).find("v 0.1 0 0\n"), std::string::npos);
  const Mesh back = read_mesh(d.file("g.ply"));
  EXPECT_TRUE(back.V == m.V);
  EXPECT_TRUE(back.face_colors == m.face_colors);
}

TEST(Attributes, ObjKeepsMaterialsGroupsObjectsAndSeams) {
  TempDir d;
  Mesh m = fully_attributed_grid();
  write_bytes(d.file("grid.mtl"), "newmtl left\nKd 1 0 0\nnewmtl right\nKd 0 0 1\n");
  m.material_libraries = {d.file("grid.mtl")};
  write_mesh(d.file("grid.obj"), m);
  const std::string text = read_bytes(d.file("grid.obj"));
  EXPECT_EQ(text.find("mtllib grid.mtl\n"), text.find("mtllib"));  // relative to the OBJ's folder
  EXPECT_NE(text.find("\no sheet\n"), std::string::npos);
  EXPECT_NE(text.find("\ng chart1\nusemtl right\n"), std::string::npos);
  const Mesh r = read_mesh(d.file("grid.obj"));
  EXPECT_TRUE(r.F == m.F);
  EXPECT_EQ(r.material_names, m.material_names);
  EXPECT_TRUE(r.face_materials == m.face_materials);
  EXPECT_EQ(r.group_names, m.group_names);
  EXPECT_TRUE(r.face_groups == m.face_groups);
  EXPECT_EQ(r.object_names, m.object_names);
  EXPECT_TRUE(r.face_objects == m.face_objects);
  EXPECT_EQ(corner_uv_error(m, r), 0.0);
  ASSERT_EQ(r.material_libraries.size(), 1u);
  EXPECT_TRUE(fs::equivalent(r.material_libraries[0], d.file("grid.mtl")));
  // Written into another folder, the mtllib path is rewritten so that it names the same file.
  fs::create_directories(d.file("sub/deeper"));
  write_mesh(d.file("sub/deeper/out.obj"), r);
  EXPECT_NE(read_bytes(d.file("sub/deeper/out.obj")).find("mtllib ../../grid.mtl\n"), std::string::npos);
  const Mesh again = read_mesh(d.file("sub/deeper/out.obj"));
  EXPECT_TRUE(fs::equivalent(again.material_libraries[0], d.file("grid.mtl")));
  // OBJ cannot hold alpha, face colours and the extra properties: named.
  const auto lost = unsupported_attributes(m, d.file("x.obj"));
  ASSERT_EQ(lost.size(), 3u);
  EXPECT_EQ(lost[0], "OBJ cannot hold vertex alpha: not written");
  EXPECT_EQ(lost[2], "OBJ cannot hold extra vertex properties ('quality', 'label', 'value'): not written");
}

TEST(Attributes, LossesAreNamedPerFormat) {
  const Mesh m = fully_attributed_grid();
  const auto stl = unsupported_attributes(m, "x.stl");
  EXPECT_NE(std::find(stl.begin(), stl.end(), "STL cannot hold vertex colours: not written"), stl.end());
  EXPECT_NE(std::find(stl.begin(), stl.end(), "STL cannot hold texture coordinates: not written"), stl.end());
  const auto off = unsupported_attributes(m, "x.off.gz");
  EXPECT_NE(std::find(off.begin(), off.end(), "OFF cannot hold materials per face: not written"), off.end());
  EXPECT_EQ(std::find(off.begin(), off.end(), "OFF cannot hold vertex colours: not written"), off.end());
  EXPECT_TRUE(unsupported_attributes(test::grid(3), "x.stl").empty());
  Mesh ply_only = test::grid(3);
  ply_only.face_colors = Eigen::MatrixXd::Ones(ply_only.F.rows(), 3);
  EXPECT_TRUE(unsupported_attributes(ply_only, "x.ply").empty());
}

TEST(Attributes, GzipRoundTripsEveryFormat) {
  TempDir d;
  const Mesh m = test::attributed_grid();
  for (const std::string ext : {"obj", "off", "ply", "stl", "glb", "gltf"}) {
    SCOPED_TRACE(ext);
    write_mesh(d.file("m." + ext), m);
    write_mesh(d.file("m." + ext + ".gz"), m);
    const std::string packed = read_bytes(d.file("m." + ext + ".gz"));
    ASSERT_GE(packed.size(), 2u);
    EXPECT_EQ(static_cast<unsigned char>(packed[0]), 0x1f);
    const Mesh a = read_mesh(d.file("m." + ext)), b = read_mesh(d.file("m." + ext + ".gz"));
    EXPECT_TRUE(a.V == b.V);
    EXPECT_TRUE(a.F == b.F);
    EXPECT_TRUE(a.vertex_colors == b.vertex_colors);
  }
}

TEST(Attributes, GltfKeepsColoursUvSeamsAndMaterials) {
  TempDir d;
  const Mesh m = fully_attributed_grid();
  for (const std::string name : {"m.glb", "m.gltf"}) {
    SCOPED_TRACE(name);
    write_mesh(d.file(name), m);
    ReadNotes notes;
    const Mesh r = read_mesh(d.file(name), notes);
    EXPECT_EQ(r.V.rows(), m.V.rows());  // vertices split at the seam are joined again
    EXPECT_EQ(r.F.rows(), m.F.rows());
    EXPECT_LT(corner_uv_error(m, r), 1e-6);  // also: every corner at its place (float32)
    ASSERT_EQ(r.vertex_colors.cols(), 4);
    EXPECT_LT(corner_color_error(m, r), 1e-6);
    EXPECT_EQ(r.material_names, m.material_names);
    EXPECT_TRUE(r.face_materials == m.face_materials);
    EXPECT_EQ(r.group_names, m.group_names);
    EXPECT_TRUE(r.face_groups == m.face_groups);
    EXPECT_EQ(r.position_type, ScalarType::Float32);
    // Extra vertex properties as "_NAME" attributes, float32 (in the order of their names).
    ASSERT_EQ(r.vertex_properties.size(), m.vertex_properties.size());
    for (const VertexProperty& mp : m.vertex_properties) {
      const auto rp = std::find_if(r.vertex_properties.begin(), r.vertex_properties.end(),
                                   [&](const VertexProperty& p) { return p.name == mp.name; });
      ASSERT_NE(rp, r.vertex_properties.end()) << mp.name;
      EXPECT_EQ(rp->type, ScalarType::Float32);
      for (Eigen::Index f = 0; f < m.F.rows(); ++f)
        for (int k = 0; k < 3; ++k)
          EXPECT_FLOAT_EQ(static_cast<float>(rp->values(r.F(f, k))), static_cast<float>(mp.values(m.F(f, k))));
    }
    EXPECT_TRUE(unsupported_attributes(m, d.file(name)) ==
                (std::vector<std::string>{"glTF cannot hold face colours: not written",
                                          "glTF cannot hold objects ('o'): not written"}));
    ASSERT_TRUE(r.gltf_document);
    // Written again from its own document: the same again.
    write_mesh(d.file("again." + name.substr(2)), r);
    const Mesh a = read_mesh(d.file("again." + name.substr(2)));
    EXPECT_TRUE(a.V == r.V);
    EXPECT_TRUE(a.F == r.F);
    EXPECT_TRUE(a.vertex_colors == r.vertex_colors);
    EXPECT_EQ(corner_uv_error(r, a), 0.0);
    EXPECT_EQ(a.material_names, r.material_names);
  }
}
