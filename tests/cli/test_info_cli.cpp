// `msmesh info`: the command-line program run on small meshes written by the tests.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;
namespace fs = std::filesystem;

namespace {

fs::path temp_folder() {
  std::random_device rd;
  fs::path p =
      fs::temp_directory_path() / ("msmesh_test_info_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
  fs::create_directories(p);
  return p;
}

}  // namespace

TEST(InfoCli, JsonSummaryOfAGrid) {
  const fs::path dir = temp_folder();
  const std::string path = (dir / "grid.ply").string();
  write_mesh(path, test::grid(3));
  const test::CliRun r = test::run_cli("info '" + path + "' --json");
  EXPECT_EQ(r.status, 0) << r.out;
  for (const char* part :
       {"\"vertices\":16", "\"faces\":18", "\"edges\":33", "\"boundary_edges\":12", "\"boundary_loops\":1",
        "\"largest_boundary_loops\":[12]", "\"components\":1", "\"non_manifold_edges\":0",
        "\"dropped_degenerate_faces\":0", "\"bbox_diagonal\":1.414213562"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " not in " << r.out;
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << "one line of JSON expected";
  fs::remove_all(dir);
}

TEST(InfoCli, TextSummaryCountsDefects) {
  const fs::path dir = temp_folder();
  // The fin (a non-manifold edge) plus an unreferenced vertex and a degenerate face.
  const std::string path = (dir / "fin.obj").string();
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fputs("v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -1 0.2\nv 0.5 0 1\nv 9 9 9\nf 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 1 2\n",
               f);
    std::fclose(f);
  }
  const test::CliRun r = test::run_cli("info '" + path + "'");
  EXPECT_EQ(r.status, 0) << r.out;
  for (const char* part :
       {"vertices:                      6", "faces:                         3", "non-manifold edges:            1",
        "unreferenced vertices:         1", "dropped degenerate faces:      1"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " not in " << r.out;
  fs::remove_all(dir);
}

TEST(InfoCli, MissingFileExitsWithOneAndNamesTheFile) {
  const test::CliRun r = test::run_cli("info /nonexistent/mesh.obj");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("/nonexistent/mesh.obj"), std::string::npos) << r.out;
}

TEST(InfoCli, StanfordBunnyAsciiPly) {
  MSMESH_REQUIRE_SHARED(path, "stanford_bunny_ply/bunny/bun_zipper.ply");
  const test::CliRun r = test::run_cli("info '" + path + "' --json");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\"vertices\":35947"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"faces\":69451"), std::string::npos) << r.out;
}

TEST(InfoCli, AreaVolumeWatertightAndGenus) {
  const fs::path dir = temp_folder();
  const std::string cube = (dir / "cube.ply").string(), torus = (dir / "torus.obj").string(),
                    grid = (dir / "grid.obj").string();
  write_mesh(cube, make_cube(2));
  write_mesh(torus, make_torus(12, 6));
  write_mesh(grid, test::grid(3));
  test::CliRun r = test::run_cli("info '" + cube + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* part :
       {"surface area:                  24\n", "volume:                        8\n",
        "watertight:                    yes", "Euler characteristic:          2", "genus:                         0\n"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " not in " << r.out;
  r = test::run_cli("info '" + torus + "' --json");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* part :
       {"\"genus\":1", "\"euler_characteristic\":0", "\"watertight\":true", "\"closed_components\":1"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " not in " << r.out;
  r = test::run_cli("info '" + grid + "' --json");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* part : {"\"area\":1,", "\"volume\":null", "\"watertight\":false", "\"euler_characteristic\":1",
                           "\"genus\":0", "\"component_details\":[{\"faces\":18,"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " not in " << r.out;
  r = test::run_cli("info '" + grid + "'");
  EXPECT_NE(r.out.find("volume:                        open (no closed component)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("genus:                         0 (surface with 1 boundary loop)"), std::string::npos) << r.out;
  fs::remove_all(dir);
}
