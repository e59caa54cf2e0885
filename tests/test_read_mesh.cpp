// Reading meshes (msmesh/read_mesh.h): triangulation and welding on read, the public meshes
// in each format, one test per kind of broken file (each must throw IoError naming the file),
// and the fuzzers' inputs as regression tests (fuzz/, scripts/fuzz): every kept crash input
// (tests/data/fuzz_regressions/<format>/) must be refused with IoError / InvalidInput or read
// as a valid mesh, never crash; every seed of the corpus (fuzz/corpus/<format>/, valid small
// meshes written by fuzz/make_corpus.py) must read as a valid mesh. Round trips through the
// writers are in test_write_mesh.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "../fuzz/mesh_check.h"
#include "../io/read_stl_binary.h"
#include "bad_files.h"
#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"
#include "msmesh/read_mesh.h"
#include "msmesh/shapes.h"
#include "msmesh/threads.h"
#include "msmesh/write_mesh.h"
#include "read_helpers.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::expect_same_read;
using msmesh::test::read_bytes;
using msmesh::test::read_from_memory;
using msmesh::test::ReadResult;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;
namespace fs = std::filesystem;

namespace {

/// Expects read_mesh(path) to throw IoError whose message names the file and contains `part`.
void expect_read_error(const std::string& path, const std::string& part = "") {
  try {
    read_mesh(path);
    ADD_FAILURE() << "no IoError for " << path;
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    if (!part.empty()) EXPECT_NE(what.find(part), std::string::npos) << what;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected IoError for " << path << ", got: " << e.what();
  }
}

std::string le32(std::uint32_t v) {
  std::string s(4, '\0');
  for (int b = 0; b < 4; ++b) s[b] = static_cast<char>((v >> (8 * b)) & 0xff);
  return s;
}
std::string le_float(float x) {
  std::uint32_t v;
  std::memcpy(&v, &x, 4);
  return le32(v);
}

/// A binary STL of the given triangles (9 floats each).
std::string binary_stl(const std::vector<std::array<float, 9>>& tris, const std::string& header = "test") {
  std::string s = header;
  s.resize(80, ' ');
  s += le32(static_cast<std::uint32_t>(tris.size()));
  for (const auto& t : tris) {
    s += le_float(0) + le_float(0) + le_float(1);
    for (float x : t) s += le_float(x);
    s += std::string(2, '\0');
  }
  return s;
}

const fs::path kSource = MSMESH_SOURCE_DIR;  // not __FILE__: ccache may make it relative
const char* const kFormats[] = {"obj", "off", "ply", "stl"};

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() != ".md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

// ---- reading ------------------------------------------------------------------------------------

TEST(IoRead, QuadObjIsTriangulated) {
  TempDir dir;
  const std::string path = dir.file("quad.obj");
  write_bytes(path,
              "# two quads\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2/1 5/2 6/3 3/4\n");
  const Mesh m = read_mesh(path);
  EXPECT_EQ(m.V.rows(), 6);
  ASSERT_EQ(m.F.rows(), 4);
  EXPECT_EQ(m.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(m.F.row(1), Eigen::RowVector3i(0, 2, 3));
  EXPECT_EQ(m.F.row(2), Eigen::RowVector3i(1, 4, 5));
  EXPECT_EQ(m.F.row(3), Eigen::RowVector3i(1, 5, 2));
}

TEST(IoRead, FacesRepeatingAVertexAreDroppedAndCounted) {
  TempDir dir;
  const std::string path = dir.file("degenerate.off");
  write_bytes(path, "OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 0 1\n2 0 1\n");
  Eigen::Index dropped = 0;
  const Mesh m = read_mesh(path, &dropped);
  EXPECT_EQ(m.F.rows(), 1);
  EXPECT_EQ(dropped, 2);
}

TEST(IoRead, UpperCaseExtension) {
  TempDir dir;
  const std::string path = dir.file("TET.OBJ");
  write_mesh(path, test::tetrahedron());
  EXPECT_EQ(read_mesh(path).F.rows(), 4);
}

TEST(IoRead, StlTrianglesAreWelded) {
  TempDir dir;
  const Mesh tet = test::tetrahedron();
  write_mesh(dir.file("tet.stl"), tet);
  const Mesh r = read_mesh(dir.file("tet.stl"));
  EXPECT_EQ(r.V.rows(), 4);
  EXPECT_EQ(r.F.rows(), 4);
}

TEST(IoRead, BinaryStlWhoseHeaderStartsWithSolid) {
  TempDir dir;
  const std::string path = dir.file("solid_header.stl");
  write_bytes(path,
              binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}}, "solid exported by a CAD tool"));
  const Mesh m = read_mesh(path);
  EXPECT_EQ(m.V.rows(), 4);
  EXPECT_EQ(m.F.rows(), 2);
}

// Binary PLY files of triangles are read straight into the mesh (read_ply.cpp
// read_binary_triangles); any other layout goes through the general reader. The same body under
// a header with one more (empty) element takes the general reader: both must give the same mesh,
// notes and errors.
namespace {

/// A binary little-endian PLY of x, y, z (float or double) and faces (uchar count, int indices),
/// with `extra_header` lines added after the face element.
std::string binary_ply(const std::vector<std::array<double, 3>>& points, const std::vector<std::vector<int>>& faces,
                       bool single, const std::string& extra_header = "") {
  const char* t = single ? "float" : "double";
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(points.size()) +
                  "\nproperty " + t + " x\nproperty " + t + " y\nproperty " + t + " z\nelement face " +
                  std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\n" + extra_header +
                  "end_header\n";
  for (const auto& p : points)
    for (double x : p) {
      if (single) {
        s += le_float(static_cast<float>(x));
      } else {
        char b[8];
        std::memcpy(b, &x, 8);
        s.append(b, 8);
      }
    }
  for (const auto& f : faces) {
    s += static_cast<char>(f.size());
    for (int i : f) s += le32(static_cast<std::uint32_t>(i));
  }
  return s;
}

}  // namespace

TEST(ReadBinaryPly, TrianglesReadStraightIntoTheMeshAsTheGeneralReaderReadsThem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::array<double, 3>> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.1, 0.7, -0.25}};
  const std::vector<std::vector<int>> two = {{0, 1, 2}, {0, 2, 3}};
  struct Case {
    const char* what;
    std::vector<std::array<double, 3>> points;
    std::vector<std::vector<int>> faces;
    std::string expected_error;  // "" when the file reads
  };
  const Case cases[] = {
      {"triangles", square, two, ""},
      {"a quad", square, {{0, 1, 2, 3}}, ""},
      {"a triangle repeating a vertex", square, {{0, 1, 2}, {0, 2, 2}, {0, 2, 3}}, ""},
      {"an index past the end", square, {{0, 1, 2}, {0, 2, 4}}, "face 1 refers to vertex 4 (0-based), out of range"},
      {"a negative index", square, {{0, 1, 2}, {-1, 2, 3}}, "face 1 refers to vertex -1"},
      {"a NaN coordinate", {{0, 0, 0}, {nan, 0, 0}, {1, 1, 0}}, {{0, 1, 2}}, "vertex 1 has a non-finite coordinate"},
      {"an infinite coordinate",
       {{0, 0, 0}, {0, std::numeric_limits<double>::infinity(), 0}, {1, 1, 0}},
       {{0, 1, 2}},
       "non-finite"},
      {"coordinates spanning more than 1e150", {{0, 0, 0}, {1e200, 0, 0}, {1, 1, 0}}, {{0, 1, 2}}, "more than 1e150"},
      {"only degenerate faces", square, {{0, 1, 1}}, "all 1 faces are degenerate"},
  };
  for (const Case& c : cases)
    for (bool single : {true, false}) {
      if (single && std::string(c.what).find("1e150") != std::string::npos) continue;  // no float holds 1e200
      SCOPED_TRACE(std::string(c.what) + (single ? " (float)" : " (double)"));
      const ReadResult direct = read_from_memory(binary_ply(c.points, c.faces, single), "ply", "direct.ply");
      ReadResult general =
          read_from_memory(binary_ply(c.points, c.faces, single, "element unused 0\n"), "ply", "direct.ply");
      expect_same_read(direct, general);
      if (c.expected_error.empty()) {
        EXPECT_EQ(direct.error, "");
        EXPECT_EQ(direct.mesh.V.rows(), static_cast<Eigen::Index>(c.points.size()));
        EXPECT_EQ(direct.mesh.position_type, single ? ScalarType::Float32 : ScalarType::Float64);
      } else {
        EXPECT_NE(direct.error.find("direct.ply: "), std::string::npos) << direct.error;
        EXPECT_NE(direct.error.find(c.expected_error), std::string::npos) << direct.error;
      }
    }
  const ReadResult r = read_from_memory(binary_ply(square, two, false), "ply", "direct.ply");
  ASSERT_EQ(r.mesh.F.rows(), 2);
  EXPECT_EQ(r.mesh.V(3, 0), 0.1);
  EXPECT_EQ(r.mesh.V(3, 1), 0.7);
  EXPECT_EQ(r.mesh.V(3, 2), -0.25);
  EXPECT_EQ(r.mesh.F(1, 0), 0);
  EXPECT_EQ(r.mesh.F(1, 1), 2);
  EXPECT_EQ(r.mesh.F(1, 2), 3);
}

TEST(ReadBinaryStl, WeldsInFirstAppearanceOrderAndDropsTrianglesRepeatingAVertex) {
  TempDir dir;
  // -0 and +0 are one vertex; the third triangle collapses to two vertices after welding.
  const std::string path = dir.file("weld.stl");
  write_bytes(
      path,
      binary_stl({{1, 0, 0, 0, 0, 0, 0, 1, 0}, {-0.f, 0, 0, 1, 0, 0, 1, 1, 0.5f}, {1, 0, 0, 1, 1, 0.5f, 1, 0, -0.f}}));
  ReadNotes notes;
  const Mesh m = read_mesh(path, notes);
  ASSERT_EQ(m.V.rows(), 4);
  ASSERT_EQ(m.F.rows(), 2);
  EXPECT_EQ(notes.dropped_degenerate, 1);
  EXPECT_EQ(m.V(0, 0), 1.0);
  EXPECT_EQ(m.V(1, 0), 0.0);
  EXPECT_EQ(m.V(2, 1), 1.0);
  EXPECT_EQ(m.V(3, 2), 0.5);
  EXPECT_EQ(m.F(0, 0), 0);
  EXPECT_EQ(m.F(0, 1), 1);
  EXPECT_EQ(m.F(0, 2), 2);
  EXPECT_EQ(m.F(1, 0), 1);
  EXPECT_EQ(m.F(1, 1), 0);
  EXPECT_EQ(m.F(1, 2), 3);
  write_bytes(dir.file("flat.stl"), binary_stl({{0, 0, 0, 1, 0, 0, 1, 0, 0}}));
  expect_read_error(dir.file("flat.stl"), "all 1 faces are degenerate (repeat a vertex)");
  const float inf = std::numeric_limits<float>::infinity();
  write_bytes(dir.file("inf.stl"), binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 0, 0, 0, inf, 0}}));
  expect_read_error(dir.file("inf.stl"), "triangle 1 has a non-finite vertex coordinate");
}

TEST(ReadBinaryStl, WeldsAsAnIndependentWelderAtEveryThreadCount) {
  // A large shuffled file (two spheres of 81920 triangles, first appearance is not face order):
  // the numbers (and the bits: the first appearance's -0 or +0), the dropped triangles and the
  // first non-finite triangle named must be those of an independent welder (std::map, first
  // appearance, -0 = +0), with one welder and with 2 and 3 ranges of the file joined
  // (read_stl_binary.h).
  const Mesh sphere = make_sphere(6);  // 81920 faces
  std::vector<std::array<float, 9>> tris;
  for (const double shift : {0.0, 1.5})
    for (Eigen::Index f = 0; f < sphere.F.rows(); ++f) {
      std::array<float, 9> t;
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c)
          t[3 * k + c] = static_cast<float>(sphere.V(sphere.F(f, k), c) + (c == 0 ? shift : 0));
      tris.push_back(t);
    }
  ASSERT_GE(tris.size() / io_detail::kStlRangeTriangles, 3u);
  std::uint32_t state = 12345;
  for (std::size_t i = tris.size() - 1; i > 0; --i) {  // a fixed shuffle: first appearance is not face order
    state = state * 1664525u + 1013904223u;
    std::swap(tris[i], tris[state % (i + 1)]);
  }
  tris[1000] = {0, 0, 0, -0.f, 0, 0, 1, 1, 1};  // repeats a vertex after welding: dropped
  tris[2000] = {-0.f, 0, 0, 1, 1, 1, 2, 0, 0};
  tris[100000] = {-0.f, 0, 0, 3, 3, 3, 4, 0, 0};  // a point of the first range, -0 in a later one
  tris[110000] = {5, -0.f, 0, 6, 6, 6, 7, 0, 0};  // a point first seen in a later range, as -0 ...
  tris[150000] = {5, 0, 0, 6, 6, 6, 8, 0, 0};     // ... and as +0 in the one after
  std::map<std::array<float, 3>, int> number;
  std::vector<std::array<float, 3>> points;
  std::vector<std::array<int, 3>> faces;
  for (const auto& t : tris) {
    std::array<int, 3> id;
    for (int k = 0; k < 3; ++k) {
      std::array<float, 3> q = {t[3 * k] + 0.0f, t[3 * k + 1] + 0.0f, t[3 * k + 2] + 0.0f};  // -0 + 0 = +0
      const auto it = number.emplace(q, static_cast<int>(points.size())).first;
      if (it->second == static_cast<int>(points.size())) points.push_back({t[3 * k], t[3 * k + 1], t[3 * k + 2]});
      id[k] = it->second;
    }
    if (id[0] != id[1] && id[1] != id[2] && id[0] != id[2]) faces.push_back(id);
  }
  TempDir dir;
  write_bytes(dir.file("big.stl"), binary_stl(tris));
  auto nan_tris = tris;
  nan_tris[50000][4] = std::numeric_limits<float>::quiet_NaN();
  nan_tris[40000][8] = std::numeric_limits<float>::infinity();
  write_bytes(dir.file("big_nan.stl"), binary_stl(nan_tris));
  const int before = threads();
  for (const int n : {1, 2, 3}) {
    SCOPED_TRACE(n);
    set_threads(n);
    ReadNotes notes;
    const Mesh m = read_mesh(dir.file("big.stl"), notes);
    ASSERT_EQ(m.V.rows(), static_cast<Eigen::Index>(points.size()));
    ASSERT_EQ(m.F.rows(), static_cast<Eigen::Index>(faces.size()));
    EXPECT_EQ(notes.dropped_degenerate, static_cast<Eigen::Index>(tris.size() - faces.size()));
    bool same = true;
    for (std::size_t i = 0; i < points.size(); ++i)
      for (int c = 0; c < 3; ++c)
        same = same && m.V(static_cast<Eigen::Index>(i), c) == points[i][c] &&
               std::signbit(m.V(static_cast<Eigen::Index>(i), c)) == std::signbit(points[i][c]);
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int k = 0; k < 3; ++k) same = same && m.F(static_cast<Eigen::Index>(f), k) == faces[f][k];
    EXPECT_TRUE(same);
    expect_read_error(dir.file("big_nan.stl"), "triangle 40000 has a non-finite vertex coordinate");
  }
  set_threads(before);
}

TEST(ReadBinary, LargeFilesAreMappedAndReadAsFromMemory) {
  // Files of 64 KB and more are mapped (read_mesh.cpp), smaller ones read into a buffer, as
  // read_mesh_from_memory reads bytes: all three give the same mesh.
  TempDir dir;
  const Mesh sphere = make_sphere(4);  // 5120 faces: 128 KB of PLY, 256 KB of STL
  for (const char* name : {"sphere.ply", "sphere.stl", "sphere.obj"}) {
    SCOPED_TRACE(name);
    const std::string path = dir.file(name);
    WriteOptions options;
    options.binary = true;
    write_mesh(path, sphere, options);
    const std::string bytes = read_bytes(path);
    ASSERT_GE(bytes.size(), 65536u);
    ReadNotes file_notes, memory_notes;
    const Mesh from_file = read_mesh(path, file_notes);
    const Mesh from_memory = read_mesh_from_memory(bytes, mesh_format_from_path(path), path, memory_notes);
    ASSERT_EQ(from_file.F.rows(), sphere.F.rows());
    EXPECT_TRUE(from_file.V == from_memory.V);
    EXPECT_TRUE(from_file.F == from_memory.F);
    if (std::string(name) != "sphere.stl") {  // STL numbers the vertices by first appearance
      EXPECT_TRUE(from_file.F == sphere.F);
      EXPECT_LT((from_file.V - sphere.V).cwiseAbs().maxCoeff(), 1e-6);
    }
    EXPECT_EQ(file_notes.dropped, memory_notes.dropped);
  }
}

TEST(IoRead, ObjRecordsOutsideTheSurfaceAreSkipped) {
  TempDir dir;
  // CGAL's OBJ reader refuses 'l' (polyline) and unknown records; they carry no faces.
  write_bytes(dir.file("lines.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\nvc 1 0 0\n");
  const Mesh m = read_mesh(dir.file("lines.obj"));
  EXPECT_EQ(m.V.rows(), 3);
  EXPECT_EQ(m.F.rows(), 1);
  // ...but they do not hide real problems.
  write_bytes(dir.file("lines_nan.obj"), "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\nl 1 2\n");
  expect_read_error(dir.file("lines_nan.obj"), "line 3: non-finite");
}

TEST(IoRead, CrLfLineEndingsAndComments) {
  TempDir dir;
  write_bytes(dir.file("crlf.obj"), "# c\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvn 0 0 1\r\nf 1//1 2//1 3//1\r\n");
  EXPECT_EQ(read_mesh(dir.file("crlf.obj")).F.rows(), 1);
  write_bytes(dir.file("comments.off"), "OFF\n# counts follow\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(read_mesh(dir.file("comments.off")).F.rows(), 1);
}

// ---- broken files -------------------------------------------------------------------------------

TEST(IoErrors, MissingFile) {
  TempDir dir;
  expect_read_error(dir.file("absent.obj"), "no such file");
}

TEST(IoErrors, UnknownExtension) {
  TempDir dir;
  write_bytes(dir.file("mesh.xyz"), "v 0 0 0\n");
  expect_read_error(dir.file("mesh.xyz"), "unknown mesh format");
  expect_read_error(dir.file("noextension"), "unknown mesh format");
}

TEST(IoErrors, EmptyFile) {
  TempDir dir;
  for (const std::string name : {"e.obj", "e.off", "e.ply", "e.stl"}) {
    write_bytes(dir.file(name), "");
    expect_read_error(dir.file(name), "empty");
  }
}

TEST(IoErrors, TruncatedBinaryPly) {
  TempDir dir;
  const std::string good = dir.file("good.ply");
  write_mesh(good, test::grid(3), WriteOptions{true});
  const std::string bytes = read_bytes(good);
  for (std::size_t cut : {bytes.size() - 1, bytes.size() - 7, bytes.size() / 2, bytes.find("end_header") + 11}) {
    const std::string path = dir.file("cut" + std::to_string(cut) + ".ply");
    write_bytes(path, bytes.substr(0, cut));
    expect_read_error(path, "truncated");
  }
  // Cut inside the header.
  write_bytes(dir.file("header.ply"), bytes.substr(0, bytes.find("end_header")));
  expect_read_error(dir.file("header.ply"), "header");
}

TEST(IoErrors, TruncatedBinaryStl) {
  TempDir dir;
  const std::string good = dir.file("good.stl");
  write_mesh(good, test::grid(3), WriteOptions{true});
  const std::string bytes = read_bytes(good);
  for (std::size_t cut : {bytes.size() - 1, bytes.size() - 50, std::size_t(90), std::size_t(84), std::size_t(40)}) {
    const std::string path = dir.file("cut" + std::to_string(cut) + ".stl");
    write_bytes(path, bytes.substr(0, cut));
    expect_read_error(path);
  }
}

TEST(IoErrors, TruncatedAsciiFiles) {
  TempDir dir;
  for (const std::string name : {"t.ply", "t.stl", "t.off", "t.obj"}) {
    const std::string good = dir.file("good_" + name);
    write_mesh(good, test::grid(3), WriteOptions{false});
    const std::string bytes = read_bytes(good);
    write_bytes(dir.file(name), bytes.substr(0, bytes.size() * 2 / 3));
    if (name == "t.obj") {
      // An OBJ cut after a line is a valid smaller mesh; cut inside the vertex block instead.
      write_bytes(dir.file(name), bytes.substr(0, bytes.find("v ", 40)));
    }
    expect_read_error(dir.file(name));
  }
}

TEST(IoErrors, WrongMagic) {
  TempDir dir;
  const std::string text = "this is not a mesh at all, just some text that goes on\n";
  for (const std::string name : {"w.ply", "w.off", "w.stl", "w.obj"}) {
    write_bytes(dir.file(name), text);
    expect_read_error(dir.file(name));
  }
  // A PLY header with a binary body of the wrong format keyword.
  write_bytes(dir.file("fmt.ply"),
              "ply\nformat binary_middle_endian 1.0\nelement vertex 1\nproperty float x\nend_header\n");
  expect_read_error(dir.file("fmt.ply"), "unknown format");
}

TEST(IoErrors, HugeHeaderCounts) {
  TempDir dir;
  const std::string vertex = "property float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  write_bytes(dir.file("ascii.ply"),
              "ply\nformat ascii 1.0\nelement vertex 999999999999\n" + vertex + face + "0 0 0\n");
  expect_read_error(dir.file("ascii.ply"), "truncated");
  write_bytes(dir.file("binary.ply"), "ply\nformat binary_little_endian 1.0\nelement vertex 999999999999\n" + vertex +
                                          face + std::string(12, '\0'));
  expect_read_error(dir.file("binary.ply"), "truncated");
  write_bytes(dir.file("faces.ply"),
              "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + vertex +
                  "element face 4000000000\nproperty list uchar int vertex_indices\nend_header\n" +
                  std::string(36 + 13, '\0'));
  expect_read_error(dir.file("faces.ply"), "truncated");
  // An element without properties would otherwise be looped over without reading anything.
  write_bytes(dir.file("empty_element.ply"),
              "ply\nformat binary_little_endian 1.0\nelement nothing 999999999999\nelement vertex 0\n" + vertex +
                  "end_header\n");
  expect_read_error(dir.file("empty_element.ply"), "truncated");
  write_bytes(dir.file("huge.off"), "OFF\n2000000000 1 0\n0 0 0\n");
  expect_read_error(dir.file("huge.off"), "truncated");
  write_bytes(dir.file("overflow.off"), "OFF\n999999999999 1 0\n0 0 0\n");
  expect_read_error(dir.file("overflow.off"));
  write_bytes(dir.file("negative.off"), "OFF\n-5 1 0\n0 0 0\n");
  expect_read_error(dir.file("negative.off"));
}

TEST(IoErrors, HugeCountsInsideTheBody) {
  TempDir dir;
  const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  std::string coords;
  for (int i = 0; i < 9; ++i) coords += le_float(float(i % 2));
  // A 32-bit list count of 2^31 - 1: CGAL would allocate it before reading.
  const std::string header = "ply\nformat binary_little_endian 1.0\n" + vertex +
                             "element face 1\nproperty list int int vertex_indices\nend_header\n";
  write_bytes(dir.file("list.ply"), header + coords + le32(0x7fffffff) + le32(0) + le32(1) + le32(2));
  expect_read_error(dir.file("list.ply"), "list count");
  const std::string ascii_header =
      "ply\nformat ascii 1.0\n" + vertex + "element face 1\nproperty list uint int vertex_indices\nend_header\n";
  write_bytes(dir.file("list_ascii.ply"), ascii_header + "0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n");
  expect_read_error(dir.file("list_ascii.ply"), "list count");
  // OFF: a face declaring four billion corners.
  write_bytes(dir.file("face.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n");
  expect_read_error(dir.file("face.off"));
  // Binary OFF (big-endian): the same with a negative count.
  std::string off = "OFF BINARY\n";
  auto be32 = [](std::int32_t v) {
    std::string s(4, '\0');
    for (int b = 0; b < 4; ++b) s[b] = static_cast<char>((static_cast<std::uint32_t>(v) >> (8 * (3 - b))) & 0xff);
    return s;
  };
  off += be32(3) + be32(1) + be32(0) + std::string(36, '\0') + be32(-1) + be32(0) + be32(1) + be32(2);
  write_bytes(dir.file("binary.off"), off);
  expect_read_error(dir.file("binary.off"));
}

TEST(IoErrors, PlyHeadersCgalWouldMisread) {
  TempDir dir;
  const std::string face =
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  // Integer coordinates: CGAL dereferences a null pointer.
  write_bytes(dir.file("int.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty int y\nproperty int z\n" + face);
  expect_read_error(dir.file("int.ply"), "float and double");
  // A property before any element: CGAL indexes an empty vector.
  write_bytes(dir.file("orphan.ply"), "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\n" + face);
  expect_read_error(dir.file("orphan.ply"), "before any element");
  // An unknown type: CGAL skips it silently and misreads the rest.
  write_bytes(dir.file("int64.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nproperty int64 id\n" +
                  face);
  expect_read_error(dir.file("int64.ply"), "int64");
  // No vertex indices in the face element.
  write_bytes(dir.file("noidx.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar float corners\nend_header\n"
              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expect_read_error(dir.file("noidx.ply"), "vertex_indices");
}

TEST(IoErrors, OffColourEntriesCgalWouldReadPastTheLine) {
  TempDir dir;
  // Five entries on a COFF vertex line: CGAL would read a third colour entry that is not there.
  write_bytes(dir.file("short.off"), "COFF\n3 1 0\n0 0 0 255 0\n1 0 0 255 0\n0 1 0 255 0\n3 0 1 2\n");
  expect_read_error(dir.file("short.off"), "colour");
  // A negative colour-map index: CGAL would index its colour table below zero.
  write_bytes(dir.file("index.off"), "COFF\n3 1 0\n0 0 0 -7\n1 0 0 1\n0 1 0 1\n3 0 1 2\n");
  expect_read_error(dir.file("index.off"), "colour");
  // Well-formed COFF is read with its colours.
  write_bytes(dir.file("good.off"), "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2\n");
  const Mesh m = read_mesh(dir.file("good.off"));
  ASSERT_EQ(m.vertex_colors.rows(), 3);
  EXPECT_DOUBLE_EQ(m.vertex_colors(1, 1), 1.0);
}

TEST(IoErrors, NonFiniteCoordinates) {
  TempDir dir;
  write_bytes(dir.file("nan.obj"), "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(dir.file("nan.obj"), "non-finite");
  write_bytes(dir.file("inf.obj"), "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(dir.file("inf.obj"), "non-finite");
  write_bytes(dir.file("nan.off"), "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n");
  expect_read_error(dir.file("nan.off"), "non-finite");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  write_bytes(dir.file("nan.stl"), binary_stl({{0, 0, 0, nan, 0, 0, 0, 1, 0}}));
  expect_read_error(dir.file("nan.stl"), "non-finite");
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (float x : {0.f, 0.f, 0.f, nan, 0.f, 0.f, 0.f, 1.f, 0.f}) ply += le_float(x);
  ply += std::string(1, '\3') + le32(0) + le32(1) + le32(2);
  write_bytes(dir.file("nan.ply"), ply);
  expect_read_error(dir.file("nan.ply"), "non-finite");
}

TEST(IoErrors, OutOfRangeFaceIndex) {
  TempDir dir;
  write_bytes(dir.file("far.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n");
  expect_read_error(dir.file("far.obj"), "vertex");
  write_bytes(dir.file("next.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");  // one past the end
  expect_read_error(dir.file("next.obj"), "line 4: face refers to vertex 4");
  write_bytes(dir.file("zero.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");  // OBJ is 1-based
  expect_read_error(dir.file("zero.obj"), "1-based");
  write_bytes(dir.file("far.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  expect_read_error(dir.file("far.off"), "out of range");
  write_bytes(dir.file("far.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
              "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  expect_read_error(dir.file("far.ply"), "out of range");
}

TEST(IoErrors, NoFacesOrNoVertices) {
  TempDir dir;
  write_bytes(dir.file("points.ply"),
              "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
              "property float z\nend_header\n0 0 0\n1 0 0\n");
  expect_read_error(dir.file("points.ply"), "no faces");
  write_bytes(dir.file("points.obj"), "v 0 0 0\nv 1 0 0\n");
  expect_read_error(dir.file("points.obj"), "no faces");
  write_bytes(dir.file("novertex.off"), "OFF\n0 0 0\n");
  expect_read_error(dir.file("novertex.off"), "no vertices");
}

TEST(IoErrors, DirectoryInsteadOfFile) {
  TempDir dir;
  fs::create_directory(dir.file("folder.obj"));
  expect_read_error(dir.file("folder.obj"), "directory");
}

// ---- public meshes ------------------------------------------------------------------------------

TEST(IoShared, ReadsEachFormatOfThePublicMeshes) {
  MSMESH_REQUIRE_SHARED(root, "SOURCES.md");
  struct Case {
    std::string rel;
    Eigen::Index vertices, faces;  // as listed in SOURCES.md
  };
  const std::vector<Case> cases = {
      {"gnf_zhang2015/fandisk/clean.obj", 6475, 12946},
      {"adaptive_patches_hurtado2018/fandisk/clean.off", 6475, 12946},
      {"stanford_bunny_ply/bunny/bun_zipper.ply", 35947, 69451},         // ascii, extra properties
      {"stanford_bunny_ply/bunny/bun_zipper_res2.ply", 8171, 16301},     // ascii
      {"gnf_zhang2015/realdata/iron_scan.ply", 85574, 168285},           // binary little-endian
      {"volgallery_coeurjolly/cubesphere/clean.stl", 10250, 20492},      // binary, welded
      {"volgallery_coeurjolly/octa_flower/clean_17k.stl", 17641, 35278}  // binary, welded
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.rel);
    const std::string path = test::shared_mesh(c.rel);
    if (path.empty()) continue;
    Eigen::Index dropped = 0;
    const Mesh m = read_mesh(path, &dropped);
    EXPECT_EQ(m.V.rows(), c.vertices);
    EXPECT_EQ(m.F.rows() + dropped, c.faces);
    EXPECT_EQ(dropped, 0);
  }
}

// ---- the fuzzers' inputs ------------------------------------------------------------------------

TEST(FuzzRegressions, CrashInputsAreRefusedOrReadValid) {
  int count = 0;
  for (const char* fmt : {"obj", "off", "ply", "stl", "gltf", "glb", "obj.gz"}) {
    for (const fs::path& p : files_in(kSource / "tests/data/fuzz_regressions" / fmt)) {
      SCOPED_TRACE(p.string());
      ++count;
      try {
        const msmesh::Mesh m = msmesh::read_mesh_from_memory(bytes_of(p), fmt, p.string());
        EXPECT_EQ(msmesh::fuzz::mesh_problem(m), "");
      } catch (const msmesh::IoError& e) {
        EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      } catch (const msmesh::InvalidInput&) {
      }
    }
  }
  EXPECT_GT(count, 0) << "no crash inputs found in " << (kSource / "tests/data/fuzz_regressions");
  RecordProperty("inputs", count);
}

TEST(FuzzRegressions, SeedCorpusReadsValid) {
  int count = 0;
  for (const char* fmt : kFormats) {
    const auto files = files_in(kSource / "fuzz/corpus" / fmt);
    EXPECT_GE(files.size(), 4u) << "no seed corpus for " << fmt << " (python3 fuzz/make_corpus.py)";
    for (const fs::path& p : files) {
      SCOPED_TRACE(p.string());
      ++count;
      try {
        const msmesh::Mesh m = msmesh::read_mesh_from_memory(bytes_of(p), fmt, p.string());
        EXPECT_EQ(msmesh::fuzz::mesh_problem(m), "");
        EXPECT_GE(m.F.rows(), 2);
      } catch (const msmesh::Error& e) {
        ADD_FAILURE() << e.what();
      }
    }
  }
  EXPECT_GT(count, 20);
}

// ---------------------------------------------------------------------------------------------
// From the catalogue of awkward meshes (docs/robustness.md); the same files through the CLI:
// cli/test_broken_files_cli.cpp, cli/test_denoise_cli.cpp, cli/test_nothing_lost_cli.cpp.

TEST(BrokenFiles, LibraryThrowsIoErrorNamingFileAndProblem) {
  TempDir d;
  for (const test::BadFile& b : test::bad_files()) {
    const std::string path = d.file(b.name);
    write_bytes(path, b.content);
    try {
      read_mesh(path);
      ADD_FAILURE() << b.name << ": expected IoError";
    } catch (const IoError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path, 0), 0u) << b.name << ": " << msg;
      EXPECT_NE(msg.find(b.problem), std::string::npos) << b.name << ": " << msg;
    }
  }
}

TEST(AwkwardMeshes, FacesRepeatingAVertexAreDroppedOnReading) {
  TempDir d;
  const std::string in = d.file("rep.obj");
  write_bytes(in, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 2 4\nf 2 4 3\n");
  Eigen::Index dropped = 0;
  const Mesh m = read_mesh(in, &dropped);
  EXPECT_EQ(dropped, 1);
  EXPECT_EQ(m.F.rows(), 2);
}

TEST(NothingLost, HandWrittenObjWithColoursTexturesAndNormals) {
  TempDir d;
  const std::string in = d.file("hand.obj");
  write_bytes(in,
              "mtllib x.mtl\n"
              "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0.1 1 1 1\n"
              "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
              "vn 0 0 1\n"
              "f 1/1/1 2/2/1 4/4/1\nf 1/1/1 4/4/1 3/3/1\n");
  const Mesh m = read_mesh(in);
  ASSERT_EQ(m.vertex_colors.rows(), 4);
  EXPECT_EQ(m.vertex_colors.row(1), Eigen::RowVector3d(0, 1, 0));
  ASSERT_EQ(m.uv.rows(), 4);
  EXPECT_EQ(m.uv.row(3), Eigen::RowVector2d(1, 1));
  ASSERT_EQ(m.vertex_normals.rows(), 4);
  EXPECT_EQ(m.vertex_normals.row(2), Eigen::RowVector3d(0, 0, 1));
  // uv with seams (one vertex, two texture coordinates) cannot be per-vertex: kept per corner.
  write_bytes(d.file("seam.obj"), test::kObjWithUvSeams);
  ReadNotes notes;
  const Mesh s = read_mesh(d.file("seam.obj"), notes);
  EXPECT_EQ(s.uv.size(), 0);
  EXPECT_TRUE(notes.uv_seams);
  ASSERT_EQ(s.texcoords.rows(), 5);
  ASSERT_EQ(s.face_texcoords.rows(), 2);
  EXPECT_EQ(s.face_texcoords.row(0), Eigen::RowVector3i(0, 1, 3));
  EXPECT_EQ(s.face_texcoords.row(1), Eigen::RowVector3i(4, 3, 2));
  EXPECT_EQ(s.texcoords.row(4), Eigen::RowVector2d(0.5, 0.5));
}

// ---- gzip and glTF ------------------------------------------------------------------------------

TEST(ReadGzip, TruncatedCorruptAndFakeGzipAreRefusedNamingTheFile) {
  TempDir d;
  write_mesh(d.file("m.ply.gz"), test::grid(8));
  const std::string good = read_bytes(d.file("m.ply.gz"));
  write_bytes(d.file("cut.ply.gz"), good.substr(0, good.size() / 2));
  expect_read_error(d.file("cut.ply.gz"), "truncated gzip file");
  std::string bad = good;
  for (std::size_t i = 20; i < 40 && i < bad.size(); ++i) bad[i] = static_cast<char>(bad[i] ^ 0x5a);
  write_bytes(d.file("bad.ply.gz"), bad);
  expect_read_error(d.file("bad.ply.gz"), "gzip file");
  write_bytes(d.file("plain.obj.gz"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  expect_read_error(d.file("plain.obj.gz"), "not gzip data");
  // Two concatenated members read as one file, as gunzip does.
  write_mesh(d.file("t.obj.gz"), test::single_triangle());
  const std::string one = read_bytes(d.file("t.obj.gz"));
  write_bytes(d.file("two.obj.gz"), one + one);
  EXPECT_EQ(read_mesh(d.file("two.obj.gz")).F.rows(), 2);
}

namespace {

std::string base64_of(const std::string& in) {
  static const char* const k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const auto b = [&](std::size_t j) { return j < in.size() ? static_cast<unsigned char>(in[j]) : 0u; };
    const std::uint32_t v = (b(i) << 16) | (b(i + 1) << 8) | b(i + 2);
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? k[v & 63] : '=';
  }
  return out;
}

/// A hand-written glTF: a unit square as 4 vertices + 6 uint16 indices, TEXCOORD_0 and a
/// material with an external texture ("tex.png"), a node with a translation.
std::string square_gltf() {
  std::string bin;
  auto put = [&bin](const void* p, std::size_t n) { bin.append(static_cast<const char*>(p), n); };
  const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const float uv[8] = {0, 1, 1, 1, 1, 0, 0, 0};  // glTF: origin at the top left
  const std::uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
  put(pos, sizeof pos);
  put(uv, sizeof uv);
  put(idx, sizeof idx);
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0,"translation":[5,0,0],"name":"placed"}],
"meshes":[{"name":"square","primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],
"materials":[{"name":"painted","pbrMetallicRoughness":{"baseColorTexture":{"index":0},"baseColorFactor":[1,0.5,0.25,1]}}],
"textures":[{"source":0}],"images":[{"uri":"tex.png"}],
"buffers":[{"byteLength":92,"uri":"data:application/octet-stream;base64,)" +
         base64_of(bin) + R"("}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":32},
{"buffer":0,"byteOffset":80,"byteLength":12}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
{"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},
{"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}]})";
}

}  // namespace

TEST(ReadGltf, AHandWrittenSceneKeepsItsMaterialTextureAndNodes) {
  TempDir d;
  fs::create_directories(d.file("in"));
  write_bytes(d.file("in/square.gltf"), square_gltf());
  write_bytes(d.file("in/tex.png"), "not really a png, kept as it is");
  const Mesh m = read_mesh(d.file("in/square.gltf"));
  ASSERT_EQ(m.V.rows(), 4);
  ASSERT_EQ(m.F.rows(), 2);
  EXPECT_EQ(m.V.row(2), Eigen::RowVector3d(1, 1, 0));  // node transforms are not applied
  ASSERT_EQ(m.uv.rows(), 4);                           // per-vertex (no seams), flipped to the bottom-left origin
  EXPECT_EQ(m.uv.row(0), Eigen::RowVector2d(0, 0));
  EXPECT_EQ(m.uv.row(2), Eigen::RowVector2d(1, 1));
  EXPECT_EQ(m.material_names, std::vector<std::string>{"painted"});
  EXPECT_EQ(m.face_materials, Eigen::Vector2i(0, 0));
  EXPECT_EQ(m.group_names, std::vector<std::string>{"square"});
  // Moved vertices written to another folder: the scene is the same, the texture still found.
  Mesh moved = m;
  moved.V.col(2).setConstant(0.25);
  fs::create_directories(d.file("out"));
  for (const std::string name : {"out/square.glb", "out/square.gltf"}) {
    SCOPED_TRACE(name);
    write_mesh(d.file(name), moved);
    const std::string bytes = read_bytes(d.file(name));
    for (const char* kept : {"\"painted\"", "baseColorFactor", "\"translation\"", "\"placed\"", "../in/tex.png"})
      EXPECT_NE(bytes.find(kept), std::string::npos) << kept;
    const Mesh r = read_mesh(d.file(name));
    EXPECT_TRUE(r.V == moved.V);
    EXPECT_TRUE(r.F == moved.F);
    EXPECT_TRUE(r.uv == moved.uv);
    EXPECT_EQ(r.material_names, m.material_names);
  }
}

TEST(ReadGltf, BrokenFilesAreRefusedNamingTheFile) {
  TempDir d;
  write_bytes(d.file("junk.glb"), std::string("glTF\x02\0\0\0garbage", 15));
  expect_read_error(d.file("junk.glb"), "not a valid GLB file");
  write_bytes(d.file("junk.gltf"), "{\"asset\": ");
  expect_read_error(d.file("junk.gltf"), "not a valid glTF file");
  std::string s = square_gltf();
  s.replace(s.find("\"count\":6"), 9, "\"count\":60");  // indices past the end of their bufferView
  write_bytes(d.file("short.gltf"), s);
  expect_read_error(d.file("short.gltf"), "runs past the end of its bufferView");
  std::string t = square_gltf();
  t.replace(t.find("\"POSITION\":0,"), 13, "");
  write_bytes(d.file("nopos.gltf"), t);
  expect_read_error(d.file("nopos.gltf"), "has no POSITION attribute");
  std::string f = square_gltf();  // float indices (the fuzzer's 2.9e23 overflowed the message)
  f.replace(f.find("\"componentType\":5123"), 20, "\"componentType\":5126");
  write_bytes(d.file("float_indices.gltf"), f);
  expect_read_error(d.file("float_indices.gltf"), "indices accessor 2 does not hold unsigned integers");
}

TEST(ReadObj, RecordsThatAreNotKeptAreNamed) {
  TempDir d;
  write_bytes(d.file("m.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\ns 1\nl 1 2\ncurv 0 1 1 2\nf 1 2 3\n");
  ReadNotes notes;
  read_mesh(d.file("m.obj"), notes);
  ASSERT_EQ(notes.dropped.size(), 3u);
  EXPECT_EQ(notes.dropped[0], "1 OBJ line elements ('l') are not kept");
  EXPECT_EQ(notes.dropped[1], "OBJ smoothing groups ('s') are not kept (normals are recomputed)");
  EXPECT_EQ(notes.dropped[2], "1 OBJ records of unknown kind (the first 'curv') are not kept");
}

TEST(FuzzRegressions, GltfAndGzipSeedsReadValid) {
  for (const char* fmt : {"gltf", "glb", "obj.gz"}) {
    const auto files = files_in(kSource / "fuzz/corpus" / fmt);
    EXPECT_GE(files.size(), 1u) << "no seed corpus for " << fmt << " (python3 fuzz/make_corpus.py)";
    for (const fs::path& p : files) {
      SCOPED_TRACE(p.string());
      const msmesh::Mesh m = msmesh::read_mesh_from_memory(bytes_of(p), fmt, p.string());
      EXPECT_EQ(msmesh::fuzz::mesh_problem(m), "");
      EXPECT_EQ(m.F.rows(), 4);
    }
  }
}
