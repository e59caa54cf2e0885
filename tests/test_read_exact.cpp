// Readers are exact or refuse (issue 16, class 5): the same mesh whatever whitespace separates
// the words and with or without a UTF-8 byte-order mark; face indices that are not integers,
// overflow or are 0 refused naming the file, the line and the word; non-convex polygons
// triangulated without overlap or inverted triangles in every format with polygons; PLY face
// lists of every integer type in ascii and both binary byte orders; ascii PLY values checked
// against their type; negative binary indices reported as they are. Each file is built here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/read_mesh.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;

namespace {

Mesh read_text(TempDir& dir, const std::string& name, const std::string& bytes) {
  const std::string path = dir.file(name);
  write_bytes(path, bytes);
  return read_mesh(path);
}

/// The IoError message of reading `bytes` as `name` (fails the test when there is none).
std::string read_error(TempDir& dir, const std::string& name, const std::string& bytes) {
  const std::string path = dir.file(name);
  write_bytes(path, bytes);
  try {
    read_mesh(path);
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(path), std::string::npos) << what;
    return what;
  }
  ADD_FAILURE() << "no IoError for " << name;
  return "";
}

void expect_same_mesh(const Mesh& a, const Mesh& b, const std::string& what) {
  ASSERT_EQ(a.V.rows(), b.V.rows()) << what;
  ASSERT_EQ(a.F.rows(), b.F.rows()) << what;
  EXPECT_TRUE(a.V == b.V) << what;
  EXPECT_TRUE(a.F == b.F) << what;
  EXPECT_TRUE(a.vertex_colors.rows() == b.vertex_colors.rows() && a.vertex_colors == b.vertex_colors) << what;
  EXPECT_TRUE(a.uv.rows() == b.uv.rows() && a.uv == b.uv) << what;
}

const std::string kObj =
    "# a square and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nvt 0 0\nvt 1 0\n"
    "vt 1 1\nvt 0 1\nvt 0.5 0.5\nf 1/1 2/2 3/3 4/4\nf 2/2 5/5 3/3\n";

std::string replace_spaces(const std::string& s, const std::string& by) {
  std::string out;
  for (char c : s) out += c == ' ' ? by : std::string(1, c);
  return out;
}

// ---- polygons -----------------------------------------------------------------------------------

struct Polygon2 {
  const char* name;
  std::vector<std::array<double, 2>> corners;  // counter-clockwise
};

std::vector<Polygon2> non_convex_polygons() {
  std::vector<Polygon2> polys = {
      {"L", {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}},
      {"U", {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}},
      {"concave_pentagon", {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}}},
      {"collinear_corner", {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}},
      // Starting at a reflex corner: a fan from it would overlap.
      {"L_from_reflex", {{1, 1}, {1, 3}, {0, 3}, {0, 0}, {2, 0}, {2, 1}}},
  };
  Polygon2 star{"star", {}};
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 ? 0.4 : 1.0, a = M_PI * k / 5;
    star.corners.push_back({r * std::cos(a), r * std::sin(a)});
  }
  polys.push_back(star);
  return polys;
}

double shoelace(const std::vector<std::array<double, 2>>& p) {
  double a = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& q = p[k];
    const auto& r = p[(k + 1) % p.size()];
    a += q[0] * r[1] - q[1] * r[0];
  }
  return a / 2;
}

/// The polygon placed in a tilted plane (so that no axis-aligned projection is exact).
Eigen::RowVector3d place(const std::array<double, 2>& p) {
  const Eigen::Vector3d u = Eigen::Vector3d(1, 0.3, 0.2).normalized();
  const Eigen::Vector3d v = (Eigen::Vector3d(0, 1, -0.4) - Eigen::Vector3d(0, 1, -0.4).dot(u) * u).normalized();
  return (p[0] * u + p[1] * v + Eigen::Vector3d(5, -2, 1)).transpose();
}

/// The polygon as one face of an OBJ, OFF and ascii / binary PLY file.
std::vector<std::pair<std::string, std::string>> polygon_files(const Polygon2& poly) {
  const std::size_t n = poly.corners.size();
  std::string obj, off = "OFF\n" + std::to_string(n) + " 1 0\n", ply;
  std::string ply_header = "element vertex " + std::to_string(n) +
                           "\nproperty double x\nproperty double y\nproperty double z\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n";
  std::string ply_ascii = "ply\nformat ascii 1.0\n" + ply_header,
              ply_le = "ply\nformat binary_little_endian 1.0\n" + ply_header;
  char buf[128];
  for (const auto& c : poly.corners) {
    const Eigen::RowVector3d x = place(c);
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g", x(0), x(1), x(2));
    obj += std::string("v ") + buf + "\n";
    off += std::string(buf) + "\n";
    ply_ascii += std::string(buf) + "\n";
    for (int d = 0; d < 3; ++d) ply_le.append(reinterpret_cast<const char*>(&x(d)), 8);  // little-endian host
  }
  obj += "f";
  off += std::to_string(n);
  ply_ascii += std::to_string(n);
  ply_le += static_cast<char>(n);
  for (std::size_t k = 0; k < n; ++k) {
    obj += " " + std::to_string(k + 1);
    off += " " + std::to_string(k);
    ply_ascii += " " + std::to_string(k);
    const std::int32_t i = static_cast<std::int32_t>(k);
    ply_le.append(reinterpret_cast<const char*>(&i), 4);
  }
  return {{"p.obj", obj + "\n"}, {"p.off", off + "\n"}, {"a.ply", ply_ascii + "\n"}, {"b.ply", ply_le}};
}

// ---- PLY of any list types ----------------------------------------------------------------------

/// `v` as `bytes` bytes in the given byte order.
std::string binary_int(long long v, int bytes, bool big) {
  std::string s(static_cast<std::size_t>(bytes), '\0');
  for (int b = 0; b < bytes; ++b)
    s[static_cast<std::size_t>(big ? bytes - 1 - b : b)] = static_cast<char>((v >> (8 * b)) & 0xff);
  return s;
}
std::string binary_float(float x, bool big) {
  std::uint32_t u;
  std::memcpy(&u, &x, 4);
  return binary_int(u, 4, big);
}
int type_bytes(const std::string& t) { return t == "char" || t == "uchar" ? 1 : t == "short" || t == "ushort" ? 2 : 4; }

/// A PLY square (two faces: a triangle and a quad over 5 vertices) with the given format,
/// list count type and index type; `indices` replaces the faces' indices when given.
std::string ply_square(const std::string& format, const std::string& count_type, const std::string& index_type,
                       std::vector<std::vector<long long>> faces = {{0, 1, 4}, {1, 2, 3, 4}}) {
  const double V[5][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 1, 0}};
  std::string s = "ply\nformat " + format +
                  " 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face " +
                  std::to_string(faces.size()) + "\nproperty list " + count_type + " " + index_type +
                  " vertex_indices\nend_header\n";
  const bool ascii = format == "ascii", big = format == "binary_big_endian";
  for (const auto& v : V)
    for (int d = 0; d < 3; ++d)
      s += ascii ? std::to_string(static_cast<int>(v[d])) + (d == 2 ? "\n" : " ") : binary_float(float(v[d]), big);
  for (const auto& f : faces) {
    s += ascii ? std::to_string(f.size()) : binary_int(static_cast<long long>(f.size()), type_bytes(count_type), big);
    for (long long i : f) s += ascii ? " " + std::to_string(i) : binary_int(i, type_bytes(index_type), big);
    if (ascii) s += "\n";
  }
  return s;
}

}  // namespace

// ---- whitespace and byte-order marks ------------------------------------------------------------

TEST(ReadExact, ObjAnyWhitespaceSeparatesLikeASpace) {
  TempDir dir;
  const Mesh ref = read_text(dir, "ref.obj", kObj);
  ASSERT_EQ(ref.F.rows(), 3);
  for (const std::string by : {"\t", " \t ", "\v", "\f", "\t\t", " \r "}) {
    const std::string bytes = replace_spaces(kObj, by);
    expect_same_mesh(read_text(dir, "ws.obj", bytes), ref, "separator " + testing::PrintToString(by));
  }
  // Leading and trailing whitespace on every line, CRLF line ends.
  std::string padded;
  for (const auto& line : {"v 0 0 0", "v 1 0 0", "v 1 1 0", "v 0 1 0", "v 2 0 0", "vt 0 0", "vt 1 0", "vt 1 1",
                           "vt 0 1", "vt 0.5 0.5", "f 1/1 2/2 3/3 4/4", "f 2/2 5/5 3/3"})
    padded += std::string("\t ") + line + " \t\r\n";
  expect_same_mesh(read_text(dir, "pad.obj", "# a comment\r\n" + padded), ref, "padded lines");
  // A comment after the corners ends the face.
  expect_same_mesh(read_text(dir, "comment.obj", kObj + "# end\n"), ref, "trailing comment");
}

TEST(ReadExact, ByteOrderMarkIsSkippedInEveryTextFormat) {
  TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  const std::vector<std::pair<std::string, std::string>> files = {
      {"m.obj", kObj},
      {"m.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"},
      {"m.ply", ply_square("ascii", "uchar", "int")},
      {"m.stl",
       "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
       "endsolid t\n"},
  };
  for (const auto& [name, bytes] : files) {
    const Mesh plain = read_text(dir, name, bytes);
    expect_same_mesh(read_text(dir, "bom_" + name, bom + bytes), plain, name);
  }
}

// ---- OBJ face indices ---------------------------------------------------------------------------

TEST(ReadExact, ObjBadIndexWordsAreRefusedNamingLineAndWord) {
  TempDir dir;
  const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\n# faces\n";
  for (const std::string bad : {"2.9", "1e3", "99999999999", "-99999999999", "0", "-0", "+1", "1//", "1/", "1/x",
                                "1/2/3/4", "x", "2,", "0x2", "1/1.5", "1//2.0"}) {
    const std::string what = read_error(dir, "bad.obj", head + "f 1 " + bad + " 3\n");
    EXPECT_NE(what.find("line 5"), std::string::npos) << bad << ": " << what;
    EXPECT_NE(what.find("'" + bad + "'"), std::string::npos) << bad << ": " << what;
  }
  // Out of range: beyond the vertices (named with the line), before the first one.
  EXPECT_NE(read_error(dir, "far.obj", head + "f 1 2 3\nf 1 2 4\n").find("line 6: face refers to vertex 4"),
            std::string::npos);
  EXPECT_NE(read_error(dir, "back.obj", head + "f -1 -2 -4\n").find("line 5"), std::string::npos);
  // A bad vertex coordinate, texture coordinate or normal is refused too.
  EXPECT_NE(read_error(dir, "coord.obj", "v 0 0 0\nv 1 0x 0\nv 0 1 0\nf 1 2 3\n").find("line 2"), std::string::npos);
  EXPECT_NE(read_error(dir, "vt.obj", head + "vt 0 y\nf 1 2 3\n").find("line 5"), std::string::npos);
  EXPECT_NE(read_error(dir, "vn.obj", head + "vn 0 0\nf 1 2 3\n").find("line 5"), std::string::npos);
}

TEST(ReadExact, ObjIndexFormsAndNegativeIndices) {
  TempDir dir;
  const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\n";
  const Mesh ref = read_text(dir, "ref.obj", v + "f 1 2 3\nf 2 4 3\n");
  for (const std::string faces : {"f 1/1 2/1 3/1\nf 2/1 4/1 3/1\n", "f 1//1 2//1 3//1\nf 2//1 4//1 3//1\n",
                                  "f 1/1/1 2/1/1 3/1/1\nf 2/1/1 4/1/1 3/1/1\n", "f -4 -3 -2\nf -3 -1 -2\n",
                                  "f -4/-1/-1 -3/-1/-1 -2/-1/-1\nf 2 4 3\n"}) {
    const Mesh m = read_text(dir, "forms.obj", v + faces);
    EXPECT_TRUE(m.F == ref.F) << faces;
    EXPECT_TRUE(m.V == ref.V) << faces;
  }
  // Relative indices count back from the vertices read so far, not from the end of the file.
  const Mesh rel = read_text(dir, "rel.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 1 1 0\nf -3 -1 -2\n");
  ASSERT_EQ(rel.F.rows(), 2);
  EXPECT_EQ(rel.F.row(0), Eigen::RowVector3i(0, 1, 2));
  EXPECT_EQ(rel.F.row(1), Eigen::RowVector3i(1, 3, 2));
}

// ---- polygons -----------------------------------------------------------------------------------

TEST(ReadExact, NonConvexPolygonsKeepTheirAreaAndOrientationInEveryFormat) {
  TempDir dir;
  for (const Polygon2& poly : non_convex_polygons()) {
    const double area = shoelace(poly.corners);
    ASSERT_GT(area, 0) << poly.name;
    const Eigen::Vector3d o = place({0, 0}).transpose(), ex = place({1, 0}).transpose(), ey = place({0, 1}).transpose();
    const Eigen::Vector3d normal = (ex - o).cross(ey - o).normalized();
    for (const auto& [name, bytes] : polygon_files(poly)) {
      const Mesh m = read_text(dir, name, bytes);
      const std::string what = std::string(poly.name) + " as " + name;
      ASSERT_EQ(m.F.rows(), static_cast<Eigen::Index>(poly.corners.size() - 2)) << what;
      double total = 0;
      for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
        const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
        const double signed_area = (b - a).cross(c - a).dot(normal) / 2;
        EXPECT_GT(signed_area, 1e-9) << what << ": triangle " << f << " inverted or degenerate";
        total += std::fabs(signed_area);
      }
      EXPECT_NEAR(total, area, 1e-9 * area) << what << ": the triangles overlap or leave a gap";
    }
  }
}

TEST(ReadExact, ConvexPolygonsGiveTheFanFromTheFirstCorner) {
  TempDir dir;
  const Mesh m = read_text(dir, "convex.obj",
                           "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 2 2 0\nv 0 2 0\nv -1 1 0\nf 1 2 3 4 5 6\n"
                           "v 5 0 0\nv 6 0 0\nv 6 1 0\nv 5 1 0\nv 5 0.5 0\nf 7 8 9 10 11\n");
  ASSERT_EQ(m.F.rows(), 7);
  const int expected[7][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {6, 7, 8}, {6, 8, 9}, {6, 9, 10}};
  for (int f = 0; f < 7; ++f) EXPECT_EQ(m.F.row(f), Eigen::RowVector3i(expected[f][0], expected[f][1], expected[f][2]));
}

// ---- PLY ----------------------------------------------------------------------------------------

TEST(ReadExact, PlyFaceListsOfEveryIntegerTypeAndFormat) {
  TempDir dir;
  Eigen::MatrixXi expected(3, 3);
  expected << 0, 1, 4, 1, 2, 3, 1, 3, 4;
  for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"})
    for (const std::string count : {"uchar", "char", "ushort", "short", "uint", "int"})
      for (const std::string index : {"uchar", "char", "ushort", "short", "uint", "int"}) {
        const Mesh m = read_text(dir, "t.ply", ply_square(format, count, index));
        EXPECT_TRUE(m.F == expected) << format << " " << count << " " << index << ":\n" << m.F;
        EXPECT_EQ(m.V.rows(), 5);
      }
}

TEST(ReadExact, PlyFloatAndDoubleCoordinatesReadAlike) {
  TempDir dir;
  std::string f = ply_square("ascii", "uchar", "int"), d = f;
  d.replace(d.find("float x"), 7, "double x");
  d.replace(d.find("float y"), 7, "double y");
  d.replace(d.find("float z"), 7, "double z");
  expect_same_mesh(read_text(dir, "f.ply", f), read_text(dir, "d.ply", d), "float vs double");
}

TEST(ReadExact, PlyAsciiValuesMustFitTheirType) {
  TempDir dir;
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const std::string faces = "3 0 1 2\n";
  const Mesh ok = read_text(dir, "ok.ply", head + "0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 0\n" + faces);
  ASSERT_EQ(ok.vertex_colors.rows(), 3);
  EXPECT_EQ(ok.vertex_colors(0, 0), 1.0);
  // A colour of 300 is refused (never wrapped to 44), as are negative, fractional ones.
  for (const std::string bad : {"300", "256", "-1", "2.5", "1e2"}) {
    const std::string what =
        read_error(dir, "c.ply", head + "0 0 0 255 0 0\n1 0 0 0 " + bad + " 0\n0 1 0 0 0 0\n" + faces);
    EXPECT_NE(what.find("vertex 1 (line 14)"), std::string::npos) << what;
    EXPECT_NE(what.find("'green' value '" + bad + "'"), std::string::npos) << what;
    EXPECT_NE(what.find("0..255"), std::string::npos) << what;
  }
  // Indices and counts too: a fractional index, an index beyond int, a negative count.
  EXPECT_NE(read_error(dir, "i.ply",
                       ply_square("ascii", "uchar", "int", {{0, 1, 4}})
                           .replace(ply_square("ascii", "uchar", "int", {{0, 1, 4}}).rfind("4\n"), 1, "2.9"))
                .find("'2.9'"),
            std::string::npos);
  EXPECT_NE(read_error(dir, "u.ply", ply_square("ascii", "uchar", "uchar", {{0, 1, 300}})).find("'300'"),
            std::string::npos);
}

TEST(ReadExact, PlyNegativeBinaryIndexIsReportedAsItIs) {
  TempDir dir;
  for (const std::string format : {"binary_little_endian", "binary_big_endian", "ascii"})
    for (const std::string index : {"int", "short", "char"}) {
      const std::string what = read_error(dir, "neg.ply", ply_square(format, "uchar", index, {{0, 1, -7}}));
      EXPECT_NE(what.find("refers to vertex -7"), std::string::npos) << format << " " << index << ": " << what;
      EXPECT_EQ(what.find("18446744073709551609"), std::string::npos) << what;
    }
  // An unsigned index beyond the vertices is reported as it is too.
  const std::string what =
      read_error(dir, "big.ply", ply_square("binary_little_endian", "uchar", "uint", {{0, 1, 4294967295}}));
  EXPECT_NE(what.find("refers to vertex 4294967295"), std::string::npos) << what;
}

TEST(ReadExact, OffFaceIndicesMustBeIntegers) {
  TempDir dir;
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  for (const std::string bad : {"1.5", "2.9", "1e-3"}) {
    const std::string what = read_error(dir, "bad.off", head + "3 0 " + bad + " 2\n");
    EXPECT_NE(what.find("line 6"), std::string::npos) << what;
    EXPECT_NE(what.find("not an integer"), std::string::npos) << what;
  }
}

// ---- why a file cannot be read (issue 16, class 7, reader side) --------------------------------

TEST(ReadErrors, SymlinkLoopUnsearchableFolderAndLongNameAreNotNoSuchFile) {
  namespace fs = std::filesystem;
  TempDir dir;
  auto message = [](const std::string& path) {
    try {
      read_mesh(path);
    } catch (const IoError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string loop = dir.file("loop.obj");
  fs::create_symlink(loop, loop);
  std::string what = message(loop);
  EXPECT_NE(what.find(loop), std::string::npos) << what;
  EXPECT_EQ(what.find("no such file"), std::string::npos) << what;
  EXPECT_NE(what.find("symbolic links"), std::string::npos) << what;

  const std::string long_name = dir.file(std::string(300, 'a') + ".obj");
  what = message(long_name);
  EXPECT_EQ(what.find("no such file"), std::string::npos) << what;
  EXPECT_NE(what.find("too long"), std::string::npos) << what;

  if (geteuid() != 0) {  // root may search any folder
    const std::string locked = dir.file("locked");
    fs::create_directory(locked);
    write_bytes(locked + "/m.obj", kObj);
    fs::permissions(locked, fs::perms::owner_read);
    what = message(locked + "/m.obj");
    fs::permissions(locked, fs::perms::owner_all);
    EXPECT_EQ(what.find("no such file"), std::string::npos) << what;
    EXPECT_NE(what.find("ermission denied"), std::string::npos) << what;
  }
  // A file that is missing is still "no such file", also below a missing folder; below a file
  // the message says that part of the path is not a folder.
  EXPECT_NE(message(dir.file("absent.obj")).find("no such file"), std::string::npos);
  EXPECT_NE(message(dir.file("nowhere/absent.obj")).find("no such file"), std::string::npos);
  write_bytes(dir.file("plain"), "x");
  EXPECT_NE(message(dir.file("plain/absent.obj")).find("not a folder"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Numbers read exactly as strtod / strtof read them (the text readers parse with fast_float,
// which is correctly rounded, and fall back to strtod for the forms it leaves).

namespace {

/// Random doubles written in many forms: shortest round-trip, 17 significant digits, few
/// digits, long digit strings (more than 19 significant digits: fast_float's slow path),
/// subnormals, large exponents (powers of ten in [min_exponent, max_exponent]), and forms only strtod reads (a leading
/// '+', hexadecimal).
std::vector<std::string> number_words(std::size_t count, std::uint64_t seed, int min_exponent = -310,
                                      int max_exponent = 140) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(min_exponent, max_exponent), form(0, 7), digit(0, 9);
  std::vector<std::string> words;
  char buf[128];
  while (words.size() < count) {
    const double x = unit(rng) * std::pow(10.0, exponent(rng));
    switch (form(rng)) {
      case 0: {
        const auto r = std::to_chars(buf, buf + sizeof buf, x);
        words.emplace_back(buf, r.ptr);
        break;
      }
      case 1:
        std::snprintf(buf, sizeof buf, "%.17g", x);
        words.emplace_back(buf);
        break;
      case 2:
        std::snprintf(buf, sizeof buf, "%.3e", x);
        words.emplace_back(buf);
        break;
      case 3: {  // 20 to 40 significant digits, then an exponent
        std::string w = x < 0 ? "-0." : "0.";
        const int n = 20 + digit(rng) * 2;
        for (int k = 0; k < n; ++k) w += static_cast<char>('0' + (k == 0 ? 1 + digit(rng) % 9 : digit(rng)));
        words.push_back(w + "e" + std::to_string(exponent(rng)));
        break;
      }
      case 4:
        std::snprintf(buf, sizeof buf, "%.6f", x);
        words.emplace_back(buf);
        break;
      case 5:
        std::snprintf(buf, sizeof buf, "%.25g", x * 1e-5);  // subnormals near the bottom of the range
        words.emplace_back(buf);
        break;
      case 6:
        std::snprintf(buf, sizeof buf, "%+.9g", x);  // a leading '+' on positive numbers
        words.emplace_back(buf);
        break;
      default:
        std::snprintf(buf, sizeof buf, "%a", x);  // hexadecimal
        words.emplace_back(buf);
        break;
    }
  }
  return words;
}

}  // namespace

TEST(ReadExact, ObjCoordinatesReadExactlyAsStrtod) {
  TempDir dir;
  const std::vector<std::string> words = number_words(3 * 3000, 11);
  std::string obj;
  for (std::size_t i = 0; i < words.size(); i += 3)
    obj += "v " + words[i] + " " + words[i + 1] + " " + words[i + 2] + "\n";
  for (std::size_t v = 1; v + 2 <= words.size() / 3; v += 3)
    obj += "f " + std::to_string(v) + " " + std::to_string(v + 1) + " " + std::to_string(v + 2) + "\n";
  const Mesh m = read_text(dir, "numbers.obj", obj);
  ASSERT_EQ(m.V.rows(), static_cast<Eigen::Index>(words.size() / 3));
  std::size_t differ = 0;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const double want = std::strtod(words[i].c_str(), nullptr);
    const double got = m.V(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3));
    if (std::memcmp(&want, &got, sizeof want) != 0 && differ++ < 5)
      ADD_FAILURE() << words[i] << ": read " << got << ", strtod gives " << want;
  }
  EXPECT_EQ(differ, 0u);
}

TEST(ReadExact, PlyAsciiFloatsReadExactlyAsStrtofAndDoublesAsStrtod) {
  TempDir dir;
  // Floats: within the float range (larger ones are infinite, refused); doubles: the whole range.
  std::vector<std::string> words = number_words(3 * 1000, 12, -50, 36);
  for (const std::string& w : number_words(3 * 1000, 13)) words.push_back(w);
  for (const bool single : {true, false}) {
    const std::size_t nv = 1000, base = single ? 0 : 3 * nv;
    const char* type = single ? "float" : "double";
    std::string ply = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(nv) + "\nproperty " + type +
                      " x\nproperty " + type + " y\nproperty " + type +
                      " z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    for (std::size_t v = 0; v < nv; ++v)
      ply += words[base + 3 * v] + " " + words[base + 3 * v + 1] + " " + words[base + 3 * v + 2] + "\n";
    ply += "3 0 1 2\n";
    const Mesh m = read_text(dir, single ? "float.ply" : "double.ply", ply);
    ASSERT_EQ(m.V.rows(), static_cast<Eigen::Index>(nv));
    std::size_t differ = 0;
    for (std::size_t i = 0; i < 3 * nv; ++i) {
      const std::string& w = words[base + i];
      const double want =
          single ? static_cast<double>(std::strtof(w.c_str(), nullptr)) : std::strtod(w.c_str(), nullptr);
      const double got = m.V(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3));
      if (std::memcmp(&want, &got, sizeof want) != 0 && differ++ < 5)
        ADD_FAILURE() << type << " " << w << ": read " << got << ", expected " << want;
    }
    EXPECT_EQ(differ, 0u) << type;
  }
}

// Binary STL: the vertices welded as CGAL's reader welded them (numbered on first appearance,
// equal coordinates one vertex, -0 and +0 alike), now through a hash table.
TEST(ReadExact, BinaryStlWeldsVerticesInOrderOfFirstAppearance) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> pick(0, 199);
  std::vector<std::array<float, 3>> pool(200);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (auto& p : pool) p = {unit(rng), unit(rng), unit(rng)};
  pool[1] = {0.0f, 0.5f, -0.0f};
  pool[2] = {-0.0f, 0.5f, 0.0f};  // equal to pool[1]: one vertex
  const std::uint32_t nt = 5000;
  std::string stl(80, ' ');
  stl.replace(0, 5, "solid");  // a binary header starting with "solid": the size decides
  stl.append(reinterpret_cast<const char*>(&nt), 4);
  std::map<std::array<float, 3>, int, bool (*)(const std::array<float, 3>&, const std::array<float, 3>&)> index(
      [](const std::array<float, 3>& a, const std::array<float, 3>& b) {
        return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());  // -0 == 0, as CGAL's map
      });
  std::vector<std::array<float, 3>> expected_v;
  std::vector<std::array<int, 3>> expected_f;
  for (std::uint32_t t = 0; t < nt; ++t) {
    int c[3] = {pick(rng), pick(rng), pick(rng)};
    while (c[1] == c[0] || (c[0] | c[1]) == 3) c[1] = pick(rng);  // 1 and 2 are one vertex
    while (c[2] == c[0] || c[2] == c[1] || (c[2] | c[0]) == 3 || (c[2] | c[1]) == 3) c[2] = pick(rng);
    const float normal[3] = {0, 0, 1};
    stl.append(reinterpret_cast<const char*>(normal), 12);
    std::array<int, 3> f{};
    for (int k = 0; k < 3; ++k) {
      const auto& p = pool[static_cast<std::size_t>(c[k])];
      stl.append(reinterpret_cast<const char*>(p.data()), 12);
      const auto it = index.emplace(p, static_cast<int>(expected_v.size())).first;
      if (it->second == static_cast<int>(expected_v.size())) expected_v.push_back(p);
      f[static_cast<std::size_t>(k)] = it->second;
    }
    expected_f.push_back(f);
    stl.append(2, '\0');
  }
  TempDir dir;
  const Mesh m = read_text(dir, "weld.stl", stl);
  ASSERT_EQ(m.V.rows(), static_cast<Eigen::Index>(expected_v.size()));
  ASSERT_EQ(m.F.rows(), static_cast<Eigen::Index>(nt));
  for (std::size_t i = 0; i < expected_v.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double want = expected_v[i][static_cast<std::size_t>(c)], got = m.V(static_cast<Eigen::Index>(i), c);
      ASSERT_EQ(std::memcmp(&want, &got, sizeof want), 0) << "vertex " << i;  // the sign of the first appearance too
    }
  for (std::uint32_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) ASSERT_EQ(m.F(t, k), expected_f[t][static_cast<std::size_t>(k)]) << "face " << t;
}
