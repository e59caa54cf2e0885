// io/read_obj_plain.h: plain OBJ files read in parallel chunks give the mesh, the notes and the
// errors that the line-by-line reader gives, and every other file is left to that reader.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../io/read_obj_plain.h"
#include "msmesh/threads.h"
#include "read_helpers.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::expect_same_read;
using msmesh::test::read_from_memory;
using msmesh::test::ReadResult;

namespace {

ReadResult read_obj_text(const std::string& text) { return read_from_memory(text, "obj", "plain.obj"); }

/// `text` read as it is, and with a texture-coordinate record added at the end, which no face
/// uses (the same mesh) but which makes the file not plain: the line-by-line reader reads it.
void expect_read_as_the_general_reader(const std::string& text) {
  const std::string general = text + (text.empty() || text.back() == '\n' ? "" : "\n") + "vt 0 0\n";
  io_detail::Soup soup;
  EXPECT_FALSE(io_detail::read_plain_obj(general, soup));
  EXPECT_FALSE(soup.direct);
  expect_same_read(read_obj_text(text), read_obj_text(general));
}

bool plain(const std::string& text) {
  io_detail::Soup soup;
  const bool taken = io_detail::read_plain_obj(text, soup);
  EXPECT_EQ(taken, soup.direct);
  return taken;
}

const std::string kSquare = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.1 0.7 -0.25\nf 1 2 3\nf 1 3 4\n";

}  // namespace

TEST(InternalReadPlainObj, PlainFilesAreReadStraightIntoTheMesh) {
  struct Case {
    const char* what;
    std::string text;
  };
  const Case cases[] = {
      {"vertices and triangles", kSquare},
      {"comments, blank lines, tabs, CR LF, comments after records",
       "# exported\n\n  \nv\t0 0 0 # first\r\nv 1 0 0\r\nv 1 1 0\r\n\tv 0.1 0.7 -0.25\r\n# faces\nf 1 2 3 #\nf\t1 3  "
       "4\r\n"},
      {"no newline at the end", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3"},
      {"faces before their vertices", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"},
      {"exponents, signs, long digits", "v -1e-3 2.5E+2 0.30000000000000004\nv 1 0 0\nv 1 1 0\nf 3 1 2\n"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    EXPECT_TRUE(plain(c.text));
    expect_read_as_the_general_reader(c.text);
    EXPECT_EQ(read_obj_text(c.text).error, "");
  }
  const ReadResult r = read_obj_text(kSquare);
  ASSERT_EQ(r.mesh.F.rows(), 2);
  EXPECT_EQ(r.mesh.V(3, 1), 0.7);
  EXPECT_EQ(r.mesh.V(3, 2), -0.25);
  EXPECT_EQ(r.mesh.F(1, 0), 0);
  EXPECT_EQ(r.mesh.F(1, 2), 3);
}

TEST(InternalReadPlainObj, EverythingElseIsLeftToTheLineByLineReader) {
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  struct Case {
    const char* what;
    std::string text;
    std::string error;  // part of the line-by-line reader's message, "" when the file reads
  };
  const Case cases[] = {
      {"a quad", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n", ""},
      {"vertex colours", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nf 1 2 3\n", ""},
      {"a fourth coordinate", v3 + "v 0 1 0 1\nf 1 2 4\n", ""},
      {"normal indices", v3 + "vn 0 0 1\nf 1//1 2//1 3//1\n", ""},
      {"negative indices", v3 + "f -3 -2 -1\n", ""},
      {"a group", v3 + "g part\nf 1 2 3\n", ""},
      {"a leading '+'", "v +1 0 0\nv 1 0 1\nv 1 1 0\nf 1 2 3\n", ""},
      {"a triangle repeating a vertex", v3 + "f 1 2 3\nf 1 1 2\n", ""},
      {"index 0", v3 + "f 0 1 2\n", "index 0"},
      {"an index past the end", v3 + "f 1 2 4\n", "face refers to vertex 4, but the file has 3 vertices"},
      {"an index beyond int", v3 + "f 1 2 99999999999\n", "does not fit in an int"},
      {"a non-finite coordinate", "v nan 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "non-finite vertex coordinate"},
      {"coordinates spanning more than 1e150", "v 0 0 0\nv 1e200 0 0\nv 1 1 0\nf 1 2 3\n", "more than 1e150"},
      {"a word glued to a number", "v 0 0 0#x\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "cannot read vertex coordinate"},
      {"too few coordinates", "v 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n", "fewer than 3 coordinates"},
      {"an index with a point", v3 + "f 1 2 3.0\n", "an index must be an integer"},
      {"a NUL byte", v3 + std::string(1, '\0') + "\nf 1 2 3\n", ""},
      {"no faces", v3, "no faces"},
      {"no vertices", "f 1 2 3\n", "no vertices"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    EXPECT_FALSE(plain(c.text));
    const ReadResult r = read_obj_text(c.text);
    if (c.error.empty()) {
      EXPECT_EQ(r.error, "");
    } else {
      EXPECT_NE(r.error.find("plain.obj"), std::string::npos) << r.error;
      EXPECT_NE(r.error.find(c.error), std::string::npos) << r.error;
    }
  }
}

TEST(InternalReadPlainObj, LargeFilesReadInChunksAsTheGeneralReaderAtEveryThreadCount) {
  // 81920 faces, ~4 MB: several chunks of whole lines; the lines at the cuts must neither be
  // lost nor read twice, and the numbering must run on across the chunks.
  const Mesh sphere = make_sphere(6);
  std::string text = "# sphere\n";
  char line[128];
  for (Eigen::Index i = 0; i < sphere.V.rows(); ++i) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", sphere.V(i, 0), sphere.V(i, 1), sphere.V(i, 2));
    text += line;
  }
  for (Eigen::Index f = 0; f < sphere.F.rows(); ++f) {
    std::snprintf(line, sizeof line, (f % 7 ? "f %d %d %d\n" : "f  %d\t%d %d \r\n"), sphere.F(f, 0) + 1,
                  sphere.F(f, 1) + 1, sphere.F(f, 2) + 1);
    text += line;
  }
  const int before = threads();
  for (const int n : {1, 2, 3}) {
    SCOPED_TRACE(n);
    set_threads(n);
    EXPECT_TRUE(plain(text));
    expect_read_as_the_general_reader(text);
    const ReadResult r = read_obj_text(text);
    EXPECT_TRUE(r.mesh.V == sphere.V);
    EXPECT_TRUE(r.mesh.F == sphere.F);
    // A bad line late in the file leaves the whole file to the line-by-line reader.
    const std::string bad = text + "f 1 2 999999\n";
    EXPECT_FALSE(plain(bad));
    EXPECT_NE(read_obj_text(bad).error.find("face refers to vertex 999999"), std::string::npos);
  }
  set_threads(before);
}
