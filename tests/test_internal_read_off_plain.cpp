// io/read_off_plain.h: plain ascii OFF files read in parallel chunks give the mesh, the notes
// and the errors that CGAL's reader gives, and every other file is left to that reader.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "../io/read_off_plain.h"
#include "msmesh/threads.h"
#include "read_helpers.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::expect_same_read;
using msmesh::test::read_from_memory;
using msmesh::test::ReadResult;

namespace {

ReadResult read_off_text(const std::string& text) { return read_from_memory(text, "off", "plain.off"); }

/// read_plain_off on the body of `text` (after "OFF" and the three counts).
bool plain(const std::string& text) {
  long long nv = 0, nf = 0, ne = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "OFF %lld %lld %lld%n", &nv, &nf, &ne, &used) != 3) return false;
  io_detail::Soup soup;
  const bool taken =
      io_detail::read_plain_off(std::string_view(text).substr(static_cast<std::size_t>(used)), nv, nf, soup);
  EXPECT_EQ(taken, soup.direct);
  return taken;
}

/// `text` read as it is, and with a comment line added at the end, which CGAL skips (the
/// same mesh) but which makes the file not plain: CGAL's reader reads it.
void expect_read_as_cgal_reads(const std::string& text) {
  const std::string general = text + (text.empty() || text.back() == '\n' ? "" : "\n") + "# end\n";
  EXPECT_FALSE(plain(general));
  expect_same_read(read_off_text(text), read_off_text(general));
}

const std::string kSquare = "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0.1 0.7 -0.25\n3 0 1 2\n3 0 2 3\n";

}  // namespace

TEST(InternalReadPlainOff, PlainFilesAreReadStraightIntoTheMesh) {
  struct Case {
    const char* what;
    std::string text;
  };
  const Case cases[] = {
      {"vertices and triangles", kSquare},
      {"blank lines, tabs, CR LF, an edge count",
       "OFF\r\n4 2 5\r\n\r\n0 0 0\r\n1\t0 0\r\n 1 1 0 \r\n0.1 0.7 -0.25\r\n\n3 0 1 2\r\n3  0 2\t3\r\n"},
      {"no newline at the end", "OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 2 0 1"},
      {"exponents, signs, long digits", "OFF\n3 1 0\n-1e-3 2.5E+2 0.30000000000000004\n1 0 0\n1 1 0\n3 2 0 1\n"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    EXPECT_TRUE(plain(c.text));
    expect_read_as_cgal_reads(c.text);
    EXPECT_EQ(read_off_text(c.text).error, "");
  }
  const ReadResult r = read_off_text(kSquare);
  ASSERT_EQ(r.mesh.F.rows(), 2);
  EXPECT_EQ(r.mesh.V(3, 1), 0.7);
  EXPECT_EQ(r.mesh.V(3, 2), -0.25);
  EXPECT_EQ(r.mesh.F(1, 0), 0);
  EXPECT_EQ(r.mesh.F(1, 2), 3);
}

TEST(InternalReadPlainOff, EverythingElseIsLeftToCgalsReader) {
  const std::string v3 = "0 0 0\n1 0 0\n1 1 0\n";
  struct Case {
    const char* what;
    std::string text;
    std::string error;  // part of the general reader's message, "" when the file reads
  };
  const Case cases[] = {
      {"a quad", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", ""},
      {"a comment", "OFF\n3 1 0\n# vertices\n" + v3 + "3 0 1 2\n", ""},
      {"a record after the faces", "OFF\n3 1 0\n" + v3 + "3 0 1 2\n3 0 1 2\n", ""},
      {"a fourth coordinate", "OFF\n3 1 0\n0 0 0 1\n1 0 0\n1 1 0\n3 0 1 2\n", ""},
      {"a face colour", "OFF\n3 1 0\n" + v3 + "3 0 1 2 255 0 0\n", ""},
      {"a triangle repeating a vertex", "OFF\n3 2 0\n" + v3 + "3 0 1 2\n3 0 0 1\n", ""},
      {"numbers CGAL splits", "OFF\n3 1 0\n1-2 0\n1 0 0\n1 1 0\n3 0 1 2\n", ""},
      {"a NUL byte", "OFF\n3 1 0\n" + v3 + std::string(1, '\0') + "\n3 0 1 2\n", "invalid vertex count"},
      {"an index past the end", "OFF\n3 1 0\n" + v3 + "3 0 1 3\n", "refers to vertex 3, out of range"},
      {"a non-finite coordinate", "OFF\n3 1 0\nnan 0 0\n1 0 0\n1 1 0\n3 0 1 2\n", "non-finite"},
      {"too few records", "OFF\n3 2 0\n" + v3 + "3 0 1 2\n", "truncated OFF file"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    EXPECT_FALSE(plain(c.text));
    const ReadResult r = read_off_text(c.text);
    if (c.error.empty()) {
      EXPECT_EQ(r.error, "");
    } else {
      EXPECT_NE(r.error.find("plain.off"), std::string::npos) << r.error;
      EXPECT_NE(r.error.find(c.error), std::string::npos) << r.error;
    }
  }
}

TEST(InternalReadPlainOff, LargeFilesReadInChunksAsCgalReadsThemAtEveryThreadCount) {
  // 81920 faces, ~3 MB: several chunks of whole lines; the record numbering must run on
  // across the cuts, vertices into faces.
  const Mesh sphere = make_sphere(6);
  std::string text = "OFF\n" + std::to_string(sphere.V.rows()) + " " + std::to_string(sphere.F.rows()) + " 0\n";
  char line[128];
  for (Eigen::Index i = 0; i < sphere.V.rows(); ++i) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", sphere.V(i, 0), sphere.V(i, 1), sphere.V(i, 2));
    text += line;
  }
  for (Eigen::Index f = 0; f < sphere.F.rows(); ++f) {
    std::snprintf(line, sizeof line, (f % 7 ? "3 %d %d %d\n" : "3  %d\t%d %d \r\n\n"), sphere.F(f, 0), sphere.F(f, 1),
                  sphere.F(f, 2));
    text += line;
  }
  const int before = threads();
  for (const int n : {1, 2, 3}) {
    SCOPED_TRACE(n);
    set_threads(n);
    EXPECT_TRUE(plain(text));
    expect_read_as_cgal_reads(text);
    const ReadResult r = read_off_text(text);
    EXPECT_TRUE(r.mesh.V == sphere.V);
    EXPECT_TRUE(r.mesh.F == sphere.F);
  }
  set_threads(before);
}
