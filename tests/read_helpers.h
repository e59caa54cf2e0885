// What the reader tests share: a read from memory as its mesh and notes or its message, and
// the comparison of a file read straight into the mesh with the general reader's reading.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "msmesh/errors.h"
#include "msmesh/read_mesh.h"

namespace msmesh::test {

/// What read_mesh_from_memory gives for `bytes`: the mesh and notes, or the error message.
struct ReadResult {
  Mesh mesh;
  ReadNotes notes;
  std::string error;
};

inline ReadResult read_from_memory(const std::string& bytes, const std::string& format, const std::string& path) {
  ReadResult r;
  try {
    r.mesh = read_mesh_from_memory(bytes, format, path, r.notes);
  } catch (const IoError& e) {
    r.error = e.what();
  }
  return r;
}

/// The same error, or the same mesh (V and F bit for bit) and notes, and neither read has a
/// per-vertex attribute (the files read straight into the mesh have none).
inline void expect_same_read(const ReadResult& a, const ReadResult& b) {
  EXPECT_EQ(a.error, b.error);
  ASSERT_EQ(a.mesh.V.rows(), b.mesh.V.rows());
  ASSERT_EQ(a.mesh.F.rows(), b.mesh.F.rows());
  EXPECT_TRUE(a.mesh.V == b.mesh.V);
  EXPECT_TRUE(a.mesh.F == b.mesh.F);
  EXPECT_EQ(a.mesh.position_type, b.mesh.position_type);
  EXPECT_EQ(a.notes.dropped_degenerate, b.notes.dropped_degenerate);
  EXPECT_EQ(a.notes.dropped, b.notes.dropped);
  EXPECT_EQ(a.notes.had_normals, b.notes.had_normals);
  for (const ReadResult* r : {&a, &b}) {
    EXPECT_EQ(r->mesh.vertex_colors.size() + r->mesh.vertex_normals.size() + r->mesh.uv.size(), 0);
    EXPECT_TRUE(r->mesh.vertex_properties.empty());
  }
}

}  // namespace msmesh::test
