// `msmesh shape`: writes a shape, lists the names, refuses unknown names and a missing output.
// The shapes themselves: test_shapes.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"
#include "msmesh/shapes.h"

using namespace msmesh;

TEST(ShapeCli, WritesListsAndRejectsUnknownNames) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("msmesh_test_shape_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "cube.off").string();

  const test::CliRun written = test::run_cli("shape cube --resolution 3 -o '" + path + "'");
  EXPECT_EQ(written.status, 0) << written.out;
  EXPECT_NE(written.out.find("108 faces"), std::string::npos) << written.out;
  EXPECT_EQ(written.out.find('\n'), written.out.size() - 1) << "one line expected: " << written.out;
  const Mesh m = read_mesh(path);
  EXPECT_EQ(m.F.rows(), 108);
  EXPECT_EQ(m.V.rows(), 56);

  const test::CliRun list = test::run_cli("shape --list");
  EXPECT_EQ(list.status, 0) << list.out;
  const test::CliRun unknown = test::run_cli("shape teapot -o '" + (dir / "teapot.obj").string() + "'");
  EXPECT_NE(unknown.status, 0);
  EXPECT_NE(unknown.out.find("teapot"), std::string::npos) << unknown.out;
  for (const std::string& name : shape_names()) {
    EXPECT_NE(list.out.find(name), std::string::npos) << list.out;
    EXPECT_NE(unknown.out.find(name), std::string::npos) << unknown.out;
  }
  EXPECT_FALSE(fs::exists(dir / "teapot.obj"));
  EXPECT_NE(test::run_cli("shape cube").status, 0);  // no output file
  fs::remove_all(dir);
}
