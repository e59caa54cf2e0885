// Attributes through the commands (docs/robustness.md, "Attributes"): a textured OBJ with
// mtllib/usemtl/groups and uv seams, a GLB scan with colours, uv and a material, gzip files,
// the notes of what a format cannot hold, new faces of inpainting. Through the library:
// test_write_mesh.cpp, test_read_mesh.cpp, test_mesh_attributes.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::run_cli;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;
namespace fs = std::filesystem;

namespace {

/// A noisy 8×8 textured sheet: uv charts split down the middle (a seam), two materials of
/// `sheet.mtl`, two groups, vertex colours; its faces grouped by chart.
std::string textured_obj(int n = 8) {
  std::string s = "# a textured test sheet\nmtllib sheet.mtl\no sheet\n";
  auto num = [](double x) { return std::to_string(x); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double z = 0.02 * (((i * 7 + j * 3) % 5) / 5.0 - 0.5);
      s += "v " + num(i / (n - 1.0)) + " " + num(j / (n - 1.0)) + " " + num(z) + " " + num((i % 4) / 3.0) + " 0.5 " +
           num((j % 3) / 2.0) + "\n";
    }
  for (int chart = 0; chart < 2; ++chart)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) s += "vt " + num(0.5 * chart + 0.5 * i / (n - 1.0)) + " " + num(j / (n - 1.0)) + "\n";
  for (int chart = 0; chart < 2; ++chart) {
    s += chart == 0 ? "g left\nusemtl red\n" : "g right\nusemtl blue\n";
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        if ((i < (n - 1) / 2) != (chart == 0)) continue;
        const int a = j * n + i + 1, b = a + 1, c = a + n, d = c + 1;
        auto corner = [&](int v) { return std::to_string(v) + "/" + std::to_string(v + chart * n * n); };
        s += "f " + corner(a) + " " + corner(b) + " " + corner(d) + "\n";
        s += "f " + corner(a) + " " + corner(d) + " " + corner(c) + "\n";
      }
  }
  return s;
}

void expect_same_attributes(const Mesh& in, const Mesh& out) {
  EXPECT_TRUE(out.F == in.F);
  EXPECT_TRUE(out.texcoords == in.texcoords);
  EXPECT_TRUE(out.face_texcoords == in.face_texcoords);
  EXPECT_TRUE(out.vertex_colors == in.vertex_colors);
  EXPECT_EQ(out.material_names, in.material_names);
  EXPECT_TRUE(out.face_materials == in.face_materials);
  EXPECT_EQ(out.group_names, in.group_names);
  EXPECT_TRUE(out.face_groups == in.face_groups);
  EXPECT_EQ(out.object_names, in.object_names);
}

}  // namespace

TEST(AttributesCli, TexturedObjComesOutOfDenoiseIntact) {
  TempDir d;
  write_bytes(d.file("sheet.obj"), textured_obj());
  write_bytes(d.file("sheet.mtl"), "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  fs::create_directories(d.file("results"));
  const auto run = run_cli("denoise " + d.file("sheet.obj") + " -o " + d.file("results/sheet.obj"));
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_EQ(run.out.find("note:"), std::string::npos) << run.out;  // nothing lost
  const Mesh in = read_mesh(d.file("sheet.obj")), out = read_mesh(d.file("results/sheet.obj"));
  ASSERT_GT(in.face_texcoords.rows(), 0);
  expect_same_attributes(in, out);
  EXPECT_FALSE(out.V == in.V);  // denoised
  // The material library is referenced from the output's folder, not copied.
  EXPECT_NE(read_bytes(d.file("results/sheet.obj")).find("mtllib ../sheet.mtl\n"), std::string::npos);
  EXPECT_FALSE(fs::exists(d.file("results/sheet.mtl")));
  ASSERT_EQ(out.material_libraries.size(), 1u);
  EXPECT_TRUE(fs::equivalent(out.material_libraries[0], d.file("sheet.mtl")));
}

TEST(AttributesCli, GlbScanComesOutOfDenoiseWithColoursUvAndMaterials) {
  TempDir d;
  write_bytes(d.file("sheet.obj"), textured_obj());
  ASSERT_EQ(run_cli("noise " + d.file("sheet.obj") + " -o " + d.file("scan.glb") + " --sigma 0.2 -q").status, 0);
  const auto run = run_cli("denoise " + d.file("scan.glb") + " -o " + d.file("clean.glb"));
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_EQ(run.out.find("note:"), std::string::npos) << run.out;
  const Mesh in = read_mesh(d.file("scan.glb")), out = read_mesh(d.file("clean.glb"));
  ASSERT_GT(in.vertex_colors.rows(), 0);
  ASSERT_GT(in.face_texcoords.rows(), 0);  // the seam is kept (vertices joined on reading)
  expect_same_attributes(in, out);
  EXPECT_EQ(out.material_names, (std::vector<std::string>{"red", "blue"}));
  EXPECT_FALSE(out.V == in.V);
  // And out again as OBJ: the same uv, materials and groups.
  ASSERT_EQ(run_cli("denoise " + d.file("clean.glb") + " -o " + d.file("clean.obj") + " -q").status, 0);
  const Mesh obj = read_mesh(d.file("clean.obj"));
  EXPECT_TRUE(obj.face_texcoords.rows() == out.F.rows());
  EXPECT_EQ(obj.material_names, out.material_names);
}

TEST(AttributesCli, LossesAreNamedInNotes) {
  TempDir d;
  write_bytes(d.file("sheet.obj"), textured_obj());
  const auto stl = run_cli("denoise " + d.file("sheet.obj") + " -o " + d.file("out.stl") + " -q");
  ASSERT_EQ(stl.status, 0) << stl.out;
  for (const char* what :
       {"STL cannot hold vertex colours", "STL cannot hold texture coordinates",
        "STL cannot hold material libraries (mtllib)", "STL cannot hold materials per face", "STL cannot hold groups"})
    EXPECT_NE(stl.out.find(d.file("out.stl") + ": " + what + ": not written"), std::string::npos) << what << stl.out;
  const auto off = run_cli("repair " + d.file("sheet.obj") + " -o " + d.file("out.off") + " --json");
  ASSERT_EQ(off.status, 0) << off.out;
  EXPECT_NE(off.out.find("\"notes\":[\""), std::string::npos) << off.out;
  EXPECT_NE(off.out.find("OFF cannot hold texture coordinates: not written"), std::string::npos) << off.out;
  // What reading dropped is named too.
  write_bytes(d.file("lines.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\n");
  const auto l = run_cli("noise " + d.file("lines.obj") + " -o " + d.file("l.ply") + " -q");
  ASSERT_EQ(l.status, 0) << l.out;
  EXPECT_NE(l.out.find("note: " + d.file("lines.obj") + ": 1 OBJ line elements ('l') are not kept"), std::string::npos)
      << l.out;
}

TEST(AttributesCli, GzipInAndOutAndBrokenGzip) {
  TempDir d;
  write_mesh(d.file("in.ply.gz"), test::noisy(test::grid(6, 0.1), 0.01));
  const auto run = run_cli("denoise " + d.file("in.ply.gz") + " -o " + d.file("out.obj.gz") + " -q");
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_EQ(read_mesh(d.file("out.obj.gz")).F.rows(), read_mesh(d.file("in.ply.gz")).F.rows());
  const std::string bytes = read_bytes(d.file("in.ply.gz"));
  write_bytes(d.file("cut.ply.gz"), bytes.substr(0, bytes.size() - 30));
  const auto bad = run_cli("denoise " + d.file("cut.ply.gz") + " -o " + d.file("x.ply") + " -q");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find(d.file("cut.ply.gz") + ": truncated gzip file"), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(d.file("x.ply")));
}

TEST(AttributesCli, InpaintedFacesTakeANeighboursMaterialAndNoUv) {
  TempDir d;
  write_bytes(d.file("sheet.obj"), textured_obj(20));
  ASSERT_EQ(
      run_cli("holes " + d.file("sheet.obj") + " -o " + d.file("holed.obj") + " --count 1 --radius 1.5 -q").status, 0);
  const Mesh holed = read_mesh(d.file("holed.obj"));
  EXPECT_EQ(holed.material_names.size(), 2u);
  ASSERT_EQ(holed.face_texcoords.rows(), holed.F.rows());
  const auto run = run_cli("inpaint " + d.file("holed.obj") + " -o " + d.file("filled.obj"));
  ASSERT_EQ(run.status, 0) << run.out;
  const Mesh out = read_mesh(d.file("filled.obj"));
  const Eigen::Index added = out.F.rows() - holed.F.rows();
  ASSERT_GT(added, 0) << run.out;
  EXPECT_NE(run.out.find("note: " + std::to_string(added) + " new faces have no texture coordinates"),
            std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("new faces took the material, group and object of a neighbouring face"), std::string::npos)
      << run.out;
  ASSERT_EQ(out.face_materials.size(), out.F.rows());
  EXPECT_TRUE(out.face_texcoords.topRows(holed.F.rows()) == holed.face_texcoords);
  for (Eigen::Index f = holed.F.rows(); f < out.F.rows(); ++f) {
    EXPECT_GE(out.face_materials(f), 0);
    EXPECT_EQ(out.face_texcoords(f, 0), -1);
  }
}
