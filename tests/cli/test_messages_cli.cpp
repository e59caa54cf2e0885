// Messages that hide the cause (issue 16, class 7): a file that cannot be opened says why
// (symlink loop, permission, name too long, a directory); errors of the work name the input
// file; coordinates whose differences overflow are refused instead of giving NaN figures;
// holes that would remove every face fail; parts of very different scale are denoised.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "cli_helpers.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/metrics.h"
#include "msmesh/topology.h"

using namespace msmesh;
namespace fs = std::filesystem;

namespace {

struct MessagesCli : ::testing::Test {
  fs::path dir;
  void SetUp() override { dir = test::temp_folder("messages"); }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir / "locked", fs::perms::owner_all, ec);
    fs::remove_all(dir);
  }
  std::string p(const std::string& name) const { return (dir / name).string(); }

  void expect_read_error(const std::string& path, const std::string& cause) {
    SCOPED_TRACE(path.substr(0, 80));
    try {
      read_mesh(path);
      ADD_FAILURE() << "read";
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(cause), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
    }
    const test::CliRun r = test::run_cli("info '" + path + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find(cause), std::string::npos) << r.out;
  }
};

TEST_F(MessagesCli, SymlinkLoopSaysSo) {
  fs::create_symlink("b.obj", dir / "a.obj");
  fs::create_symlink("a.obj", dir / "b.obj");
  expect_read_error(p("a.obj"), "symbolic links");
}

TEST_F(MessagesCli, NameTooLongSaysSo) {
  expect_read_error(p(std::string(300, 'x') + ".obj"), "too long");
  std::string deep = dir.string();
  for (int i = 0; i < 25; ++i) deep += "/" + std::string(200, 'd');
  expect_read_error(deep + ".obj", "too long");
}

TEST_F(MessagesCli, DirectoryAndNotAFolderSaySo) {
  fs::create_directory(dir / "dir.obj");
  expect_read_error(p("dir.obj"), "is a directory");
  write_mesh(p("m.obj"), test::tetrahedron());
  expect_read_error(p("m.obj/x.obj"), "not a folder");
}

TEST_F(MessagesCli, PermissionProblemSaysSo) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads any file (bench/robustness runs this case as nobody)";
  write_mesh(p("secret.obj"), test::tetrahedron());
  fs::permissions(p("secret.obj"), fs::perms::none);
  expect_read_error(p("secret.obj"), "permission denied");
}

TEST_F(MessagesCli, MissingFileStillSaysNoSuchFile) {
  try {
    read_mesh(p("none.obj"));
    ADD_FAILURE();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("none.obj: no such file"), std::string::npos) << e.what();
  }
}

TEST_F(MessagesCli, ErrorsOfTheWorkNameTheInput) {
  Mesh m = test::grid(4);
  m.V *= 1e300;  // coordinates whose squared differences overflow
  write_mesh(p("huge.obj"), m);
  for (const std::string& cmd :
       {"denoise " + p("huge.obj") + " -o " + p("o.obj"), "eval " + p("huge.obj") + " --truth " + p("huge.obj"),
        "noise " + p("huge.obj") + " -o " + p("n.obj")}) {
    SCOPED_TRACE(cmd);
    const test::CliRun r = test::run_cli(cmd);
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("msmesh: error: " + p("huge.obj") + ": "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("overflow"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(fs::exists(p("o.obj")));
  write_mesh(p("holed.obj"), test::grid_with_hole());
  const test::CliRun r = test::run_cli("inpaint " + p("holed.obj") + " -o " + p("f.obj") + " --holes 7");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(p("holed.obj") + ": inpainting: hole index 7"), std::string::npos) << r.out;
}

TEST_F(MessagesCli, HolesThatRemoveEveryFaceFail) {
  write_mesh(p("t.obj"), test::tetrahedron());
  const test::CliRun r = test::run_cli("holes " + p("t.obj") + " -o " + p("h.obj") + " --count 1 --radius 100");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("every face"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(p("h.obj")));
}

TEST(MessagesLibrary, OverflowingCoordinatesAreRefusedNotNaN) {
  Mesh m = test::grid(3);
  m.V *= 1e308;
  EXPECT_THROW(validate_mesh(m.V, m.F, "mesh"), InvalidInput);
  EXPECT_THROW(denoise(m.V, m.F), InvalidInput);
  EXPECT_THROW(evaluate(m.V, m.F, m.V, m.F), InvalidInput);
  m.V /= 1e308;
  m.V *= 1e100;  // large but safe: processed
  EXPECT_NO_THROW(validate_mesh(m.V, m.F, "mesh"));
}

TEST(MessagesLibrary, PartsOfVeryDifferentScaleAreEachDenoised) {
  // A noisy grid beside a copy 1e-5 its size, each noisy at its own scale: both get closer
  // to the clean grids (before, the small part was left to the large part's scale).
  const Mesh clean = test::grid(8);
  Mesh noisy = clean;
  for (Eigen::Index i = 0; i < noisy.V.rows(); ++i)
    noisy.V(i, 2) += 0.02 * (static_cast<double>((i * 7919) % 13) / 13 - 0.5);
  const Eigen::Index n = clean.V.rows();
  Eigen::MatrixXd V(2 * n, 3), C(2 * n, 3);
  V << noisy.V, noisy.V * 1e-5;
  C << clean.V, clean.V * 1e-5;
  Eigen::MatrixXi F(2 * clean.F.rows(), 3);
  F << clean.F, clean.F.array() + static_cast<int>(n);
  const DenoiseResult r = denoise(V, F);
  ASSERT_TRUE(r.V.allFinite());
  const double before_small = (V.bottomRows(n) - C.bottomRows(n)).norm();
  const double after_small = (r.V.bottomRows(n) - C.bottomRows(n)).norm();
  EXPECT_LT(after_small, before_small);
  EXPECT_EQ(r.normals.rows(), F.rows());
  EXPECT_EQ(r.v.size(), build_topology(F, V.rows()).num_edges());
  EXPECT_LT((r.V.topRows(n) - C.topRows(n)).norm(), (V.topRows(n) - C.topRows(n)).norm());
}

}  // namespace
