// Writing polylines (msmesh/write_polylines.h): OBJ and PLY bytes, refused indices and formats.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/write_polylines.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::TempDir;

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
