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
  EXPECT_EQ(mesh_format_from_path("scan.GLB"), "glb");
  EXPECT_EQ(mesh_format_from_path("scene.gltf"), "gltf");
}

TEST(MeshFormat, GzipNamesTheFormatUnderIt) {
  EXPECT_EQ(mesh_format_from_path("m.obj.gz"), "obj");
  EXPECT_EQ(mesh_format_from_path("d/m.PLY.GZ"), "ply");
  EXPECT_TRUE(is_gzip_path("m.off.Gz"));
  EXPECT_FALSE(is_gzip_path("m.off"));
  try {
    mesh_format_from_path("m.tar.gz");
    ADD_FAILURE() << "no IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("'.tar' under .gz"), std::string::npos) << e.what();
  }
}

TEST(MeshFormat, OtherExtensionsAreRefusedNamingThePath) {
  for (const std::string path : {"mesh.xyz", "noextension", "m.gz"}) {
    SCOPED_TRACE(path);
    try {
      mesh_format_from_path(path);
      ADD_FAILURE() << "no IoError";
    } catch (const IoError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": unknown mesh format", 0), 0u) << what;
      EXPECT_NE(what.find("expected .obj, .off, .ply, .stl, .gltf or .glb, optionally followed by .gz"),
                std::string::npos)
          << what;
    }
  }
}
