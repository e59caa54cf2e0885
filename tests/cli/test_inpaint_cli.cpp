// `msmesh holes` and `msmesh inpaint`: listing, filling with --truth and --json, refusing to
// overwrite the input, a mesh without holes. The library: test_inpaint.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"
#include "msmesh/holes.h"
#include "msmesh/io.h"
#include "msmesh/shapes.h"

using namespace msmesh;
namespace fs = std::filesystem;

TEST(InpaintCli, ListsFillsAndRefusesToOverwriteTheInput) {
  const fs::path dir = test::temp_folder("inpaint");
  const Mesh cube = make_cube(8);
  const std::string truth = (dir / "cube.obj").string(), holes = (dir / "holes.obj").string(),
                    out = (dir / "out.obj").string();
  write_mesh(truth, cube);
  test::CliRun r =
      test::run_cli("holes '" + truth + "' -o '" + holes + "' --count 2 --radius 2 --seed 3 --on-features");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("punched 2 of 2"), std::string::npos) << r.out;

  r = test::run_cli("inpaint '" + holes + "' --list");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("2 boundary loops"), std::string::npos) << r.out;

  r = test::run_cli("inpaint '" + holes + "' -o '" + out + "' --truth '" + truth + "' --json -q");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* part : {"\"filled\":2", "\"holes_found\":2", "\"errors\":{", "\"rms_e3\":"})
    EXPECT_NE(r.out.find(part), std::string::npos) << part << " not in " << r.out;
  EXPECT_TRUE(find_holes(read_mesh(out).V, read_mesh(out).F).empty());

  r = test::run_cli("inpaint '" + holes + "' -o '" + holes + "'");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.out.find("refusing to overwrite"), std::string::npos) << r.out;

  r = test::run_cli("inpaint '" + truth + "' -o '" + out + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("no holes"), std::string::npos) << r.out;
  const Mesh same = read_mesh(out);
  EXPECT_EQ(same.F, cube.F);
  EXPECT_LT((same.V - cube.V).cwiseAbs().maxCoeff(), 1e-12);
  fs::remove_all(dir);
}
