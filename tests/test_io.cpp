// io.h gathers the io library: including it alone gives every concept (formats, reading,
// writing meshes and polylines, atomic files), which work together here. The concepts'
// own tests: test_mesh_format.cpp, test_read_mesh.cpp, test_write_mesh.cpp,
// test_write_polylines.cpp, test_atomic_file.cpp.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "test_helpers.h"

using namespace msmesh;

TEST(Io, TheGatheringHeaderOffersEveryConcept) {
  test::TempDir d;
  const Mesh m = test::tetrahedron();
  for (const std::string name : {"t.obj", "t.off", "t.ply", "t.stl"}) {
    const std::string path = d.file(name);
    write_mesh(path, m);
    EXPECT_EQ(mesh_format_from_path(path), name.substr(2));
    const Mesh r = read_mesh(path);
    EXPECT_EQ(r.F.rows(), 4) << name;
    EXPECT_LT((read_mesh_from_memory(test::read_bytes(path), name.substr(2), name).V - r.V).norm(), 1e-12) << name;
  }
  write_polylines(d.file("lines.obj"), m.V, std::vector<std::vector<int>>{{0, 1, 2}});
  EXPECT_NE(test::read_bytes(d.file("lines.obj")).find("l "), std::string::npos);
  write_text_file(d.file("note.txt"), "hello\n");
  EXPECT_EQ(test::read_bytes(d.file("note.txt")), "hello\n");
  EXPECT_THROW(mesh_format_from_path(d.file("t.xyz")), IoError);
}
