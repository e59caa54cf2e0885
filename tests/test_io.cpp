// Reading and writing meshes: round trips through every format, triangulation and welding on
// read, and one test per kind of broken file (each must throw IoError naming the file).
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::write_bytes;
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

}  // namespace

// ---- round trips ------------------------------------------------------------------------------

TEST(IoRoundTrip, EveryFormatKeepsVerticesAndFaces) {
  TempDir dir;
  const Mesh m = awkward_mesh();
  struct Case {
    std::string name;
    bool binary;
  };
  for (const Case& c : {Case{"m.obj", false}, Case{"m.off", false}, Case{"ascii.ply", false}, Case{"binary.ply", true}}) {
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

TEST(IoRead, QuadObjIsTriangulated) {
  TempDir dir;
  const std::string path = dir.file("quad.obj");
  write_bytes(path, "# two quads\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nf 1 2 3 4\nf 2/1 5/2 6/3 3/4\n");
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
  EXPECT_EQ(mesh_format_from_path("a/b.PlY"), "ply");
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
  write_bytes(path, binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}}, "solid exported by a CAD tool"));
  const Mesh m = read_mesh(path);
  EXPECT_EQ(m.V.rows(), 4);
  EXPECT_EQ(m.F.rows(), 2);
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

// ---- broken files ------------------------------------------------------------------------------

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
  write_bytes(dir.file("fmt.ply"), "ply\nformat binary_middle_endian 1.0\nelement vertex 1\nproperty float x\nend_header\n");
  expect_read_error(dir.file("fmt.ply"), "unknown format");
}

TEST(IoErrors, HugeHeaderCounts) {
  TempDir dir;
  const std::string vertex = "property float x\nproperty float y\nproperty float z\n";
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  write_bytes(dir.file("ascii.ply"), "ply\nformat ascii 1.0\nelement vertex 999999999999\n" + vertex + face + "0 0 0\n");
  expect_read_error(dir.file("ascii.ply"), "truncated");
  write_bytes(dir.file("binary.ply"),
              "ply\nformat binary_little_endian 1.0\nelement vertex 999999999999\n" + vertex + face + std::string(12, '\0'));
  expect_read_error(dir.file("binary.ply"), "truncated");
  write_bytes(dir.file("faces.ply"), "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + vertex +
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
  const std::string header =
      "ply\nformat binary_little_endian 1.0\n" + vertex + "element face 1\nproperty list int int vertex_indices\nend_header\n";
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
  const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  // Integer coordinates: CGAL dereferences a null pointer.
  write_bytes(dir.file("int.ply"),
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty int x\nproperty int y\nproperty int z\n" + face);
  expect_read_error(dir.file("int.ply"), "float and double");
  // A property before any element: CGAL indexes an empty vector.
  write_bytes(dir.file("orphan.ply"), "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\n" + face);
  expect_read_error(dir.file("orphan.ply"), "before any element");
  // An unknown type: CGAL skips it silently and misreads the rest.
  write_bytes(dir.file("int64.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                     "property float z\nproperty int64 id\n" + face);
  expect_read_error(dir.file("int64.ply"), "int64");
  // No vertex indices in the face element.
  write_bytes(dir.file("noidx.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
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
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
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
  write_bytes(dir.file("far.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                   "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                   "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  expect_read_error(dir.file("far.ply"), "out of range");
}

TEST(IoErrors, NoFacesOrNoVertices) {
  TempDir dir;
  write_bytes(dir.file("points.ply"), "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
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

// ---- writing -----------------------------------------------------------------------------------

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
  const std::vector<std::string> expected = {"a.obj", "a.off", "a.ply", "a.stl", "colors.ply", "lines.obj", "notes.txt"};
  EXPECT_EQ(dir.listing(), expected);
}

TEST(IoWrite, ExceptionWhileWritingKeepsTheOldFile) {
  TempDir dir;
  const std::string path = dir.file("keep.txt");
  write_text_file(path, "old");
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw InvalidInput("stop");
                                     }),
               InvalidInput);
  EXPECT_EQ(read_bytes(path), "old");
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"keep.txt"});
  EXPECT_THROW(write_text_file(dir.path().string(), "x"), IoError);  // a folder
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
    EXPECT_NE(bytes.find("element face 4\nproperty list uchar int vertex_indices\nproperty uchar red\n"), std::string::npos);
    if (!binary) EXPECT_NE(bytes.find("3 1 3 2 128 128 128\n"), std::string::npos);
    const Mesh r = read_mesh(path);
    EXPECT_TRUE(r.F == m.F);
  }
  EXPECT_THROW(write_ply_face_colors(dir.file("c.ply"), m, Eigen::MatrixXd::Zero(3, 3)), InvalidInput);
}

TEST(IoWrite, Polylines) {
  TempDir dir;
  Eigen::MatrixXd P(4, 3);
  P << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5, 0.25, 0.125;
  write_polylines(dir.file("l.obj"), P, {{0, 1, 2}, {2, 3}});
  EXPECT_EQ(read_bytes(dir.file("l.obj")),
            "# written by msmesh\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 0.25 0.125\nl 1 2 3\nl 3 4\n");
  write_polylines(dir.file("l.ply"), P, {{0, 1, 2}, {2, 3}});
  const std::string ply = read_bytes(dir.file("l.ply"));
  EXPECT_NE(ply.find("element edge 3\nproperty int vertex1\nproperty int vertex2\nend_header\n"), std::string::npos);
  EXPECT_NE(ply.find("0 1\n1 2\n2 3\n"), std::string::npos);
  EXPECT_THROW(write_polylines(dir.file("l.obj"), P, {{0, 4}}), InvalidInput);
  EXPECT_THROW(write_polylines(dir.file("l.stl"), P, {{0, 1}}), IoError);
}

// ---- public meshes -----------------------------------------------------------------------------

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

TEST(IoShared, AsciiAndBinaryPlyOfTheBunnyAgree) {
  MSMESH_REQUIRE_SHARED(path, "stanford_bunny_ply/bunny/bun_zipper.ply");
  TempDir dir;
  const Mesh m = read_mesh(path);
  write_mesh(dir.file("bunny.ply"), m, WriteOptions{true});
  const Mesh b = read_mesh(dir.file("bunny.ply"));
  EXPECT_TRUE(b.V == m.V);
  EXPECT_TRUE(b.F == m.F);
}
