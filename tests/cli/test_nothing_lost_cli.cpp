// Nothing lost (docs/robustness.md): the input is never overwritten without --in-place, a
// failed run keeps an existing output, colours/uv/normals go through `msmesh denoise`, also
// OBJ uv with seams. Through the library: test_read_mesh.cpp, test_write_mesh.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::run_cli;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;
namespace fs = std::filesystem;

TEST(NothingLost, InputIsNeverOverwrittenWithoutInPlace) {
  TempDir d;
  const std::string in = d.file("m.ply");
  write_mesh(in, test::noisy(test::grid(5, 0.1), 0.01));
  const std::string before = read_bytes(in);
  for (const std::string cmd : {"denoise", "repair"}) {
    for (const std::string& out : {in, d.file("./m.ply")}) {
      const auto run = run_cli(cmd + " " + in + " -o " + out + " -q");
      EXPECT_EQ(run.status, 2) << run.out;  // a usage error (more cases: test_outputs_cli.cpp)
      EXPECT_NE(run.out.find("refusing to overwrite the input file"), std::string::npos) << run.out;
      EXPECT_EQ(read_bytes(in), before);
    }
  }
  const auto run = run_cli("denoise " + in + " -o " + in + " -q --in-place");
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_NE(read_bytes(in), before);
  EXPECT_EQ(d.entries(), 1u);
}

TEST(NothingLost, FailedRunKeepsAnExistingOutput) {
  TempDir d;
  const std::string in = d.file("m.ply"), out = d.file("out.ply");
  write_mesh(in, test::grid(4, 0.1));
  write_bytes(out, "previous result");
  const auto run = run_cli("denoise " + in + " -o " + out + " --alpha -1");
  EXPECT_EQ(run.status, 2);  // a usage error
  EXPECT_EQ(read_bytes(out), "previous result");
  EXPECT_EQ(d.entries(), 2u);
}

namespace {

void expect_attributes_kept(const Mesh& in, const Mesh& out, bool colors, bool uv, bool normals,
                            const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(out.V.rows(), in.V.rows());
  EXPECT_EQ(out.F, in.F);
  if (colors) {
    ASSERT_EQ(out.vertex_colors.rows(), in.V.rows());
    EXPECT_LT((out.vertex_colors - in.vertex_colors).cwiseAbs().maxCoeff(), 0.5 / 255);
  }
  if (uv) {
    ASSERT_EQ(out.uv.rows(), in.V.rows());
    EXPECT_LT((out.uv - in.uv).cwiseAbs().maxCoeff(), 1e-6);
  }
  if (normals) {
    ASSERT_EQ(out.vertex_normals.rows(), in.V.rows());
    // Recomputed for the result, not copied from the input.
    const Eigen::MatrixXd expected = vertex_normals(out.V, out.F);
    EXPECT_LT((out.vertex_normals - expected).cwiseAbs().maxCoeff(), 1e-5);
  }
}

}  // namespace

TEST(NothingLost, DenoiseCarriesColoursUvAndRecomputedNormals) {
  TempDir d;
  const Mesh m = test::attributed_grid();
  for (const std::string ext : {"ply", "obj"}) {
    const std::string in = d.file("in." + ext), out = d.file("out." + ext);
    write_mesh(in, m);
    for (const std::string method : {"nmstv", "bilateral"}) {
      const auto run = run_cli("denoise " + in + " -o " + out + " -q --method " + method);
      ASSERT_EQ(run.status, 0) << run.out;
      expect_attributes_kept(m, read_mesh(out), true, true, true, ext + " " + method);
    }
  }
  // OFF has colours (COFF) but no uv; normals (NOFF) are not written.
  Mesh c = m;
  c.uv.resize(0, 0);
  c.vertex_normals.resize(0, 0);
  write_mesh(d.file("in.off"), c);
  const auto run = run_cli("denoise " + d.file("in.off") + " -o " + d.file("out.off") + " -q");
  ASSERT_EQ(run.status, 0) << run.out;
  expect_attributes_kept(c, read_mesh(d.file("out.off")), true, false, false, "off");
}

TEST(NothingLostCli, HandWrittenObjWithColoursTexturesAndNormals) {
  // uv with seams (one vertex, two texture coordinates) cannot be per-vertex: they are kept
  // per corner through denoise (more: test_attributes_cli.cpp).
  TempDir d;
  write_bytes(d.file("seam.obj"), test::kObjWithUvSeams);
  const auto run = run_cli("denoise " + d.file("seam.obj") + " -o " + d.file("out.obj") + " -q");
  ASSERT_EQ(run.status, 0) << run.out;
  const Mesh in = read_mesh(d.file("seam.obj")), out = read_mesh(d.file("out.obj"));
  EXPECT_TRUE(out.texcoords == in.texcoords);
  EXPECT_TRUE(out.face_texcoords == in.face_texcoords);
}
