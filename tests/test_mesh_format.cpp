// The format a path names (msmesh/mesh_format.h).
#include <gtest/gtest.h>

#include <string>

#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"

using namespace msmesh;

TEST(MeshFormat, FromTheExtensionIgnoringCase) {
  EXPECT_EQ(mesh_format_from_path("a/b.PlY"), "ply");
  EXPECT_EQ(mesh_format_from_path("m.obj"), "obj");
  EXPECT_EQ(mesh_format_from_path("dir.v2/m.OFF"), "off");
  EXPECT_EQ(mesh_format_from_path("/tmp/part.Stl"), "stl");
}

TEST(MeshFormat, OtherExtensionsAreRefusedNamingThePath) {
  for (const std::string path : {"mesh.xyz", "noextension", "m.obj.gz"}) {
    SCOPED_TRACE(path);
    try {
      mesh_format_from_path(path);
      ADD_FAILURE() << "no IoError";
    } catch (const IoError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": unknown mesh format", 0), 0u) << what;
      EXPECT_NE(what.find("expected .obj, .off, .ply or .stl"), std::string::npos) << what;
    }
  }
}
