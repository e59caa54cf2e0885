// Broken files (docs/robustness.md, "Files and arrays that are refused") through `msmesh
// denoise`, `repair`, `info` and `eval`: exit status 1, the file and the problem in the
// message, no output and no temporary file left. Through the library: test_read_mesh.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bad_files.h"
#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;
using msmesh::test::run_cli;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;
namespace fs = std::filesystem;

TEST(BrokenFiles, CliExitsNonZeroNamesFileAndProblemAndWritesNothing) {
  TempDir d;
  for (const test::BadFile& b : test::bad_files()) {
    const std::string path = d.file(b.name);
    write_bytes(path, b.content);
    for (const std::string cmd : {"denoise", "repair", "info", "eval"}) {
      const std::string out = d.file(std::string("out_") + cmd + ".ply");
      std::string args = cmd + " " + path;
      if (cmd == "denoise" || cmd == "repair") args += " -o " + out;
      if (cmd == "eval") args += " --truth " + path;
      const auto run = run_cli(args);
      EXPECT_EQ(run.status, 1) << cmd << " " << b.name << ": " << run.out;
      EXPECT_NE(run.out.find("msmesh: error: " + path), std::string::npos) << cmd << " " << b.name << ": " << run.out;
      EXPECT_NE(run.out.find(b.problem), std::string::npos) << cmd << " " << b.name << ": " << run.out;
      EXPECT_FALSE(fs::exists(out)) << cmd << " " << b.name;
    }
  }
  // Only the inputs remain: no output and no temporary file.
  EXPECT_EQ(d.entries(), test::bad_files().size());
}

TEST(BrokenFiles, MissingInputAndUnwritableOutput) {
  TempDir d;
  const std::string missing = d.file("missing.ply");
  auto run = run_cli("denoise " + missing + " -o " + d.file("o.ply"));
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.out.find(missing + ": no such file"), std::string::npos) << run.out;
  const std::string in = d.file("tet.ply");
  write_mesh(in, test::tetrahedron());
  const std::string bad_out = d.file("no/such/folder/out.ply");
  run = run_cli("denoise " + in + " -o " + bad_out + " -q");
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find(bad_out), std::string::npos) << run.out;
  EXPECT_EQ(d.entries(), 1u);
}
