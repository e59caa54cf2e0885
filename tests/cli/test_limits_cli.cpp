// Limits (docs/robustness.md): parameters out of range name the valid range (exit status 2, no
// output), and a denoise beyond the memory limit fails cleanly. The library's check_memory:
// test_memory.cpp.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;
using msmesh::test::run_cli;
using msmesh::test::TempDir;
namespace fs = std::filesystem;

TEST(Limits, ParametersOutOfRangeNameTheValidRange) {
  TempDir d;
  const std::string in = d.file("m.ply"), out = d.file("o.ply");
  write_mesh(in, test::grid(4, 0.1));
  const std::pair<std::string, std::string> cases[] = {
      {"--alpha -1", "> 0"},
      {"--alpha nan", "> 0"},
      {"--epsilon 0", "> 0"},
      {"--nu 2", "(0, 1.618"},
      {"--v0 1.5", "[0, 1]"},
      {"--normal-iterations 0", "[1, 100000]"},
      {"--vertex-iterations 1000000", "[1, 100000]"},
      {"--omega2 -1", ">= 0"},
      {"--method bilateral --sigma-r 3", "(0, 2]"},
  };
  for (const auto& [args, range] : cases) {
    const auto run = run_cli("denoise " + in + " -o " + out + " " + args);
    EXPECT_EQ(run.status, 2) << args << ": " << run.out;  // a usage error
    EXPECT_NE(run.out.find("out of range"), std::string::npos) << args << ": " << run.out;
    EXPECT_NE(run.out.find(range), std::string::npos) << args << ": " << run.out;
    EXPECT_FALSE(fs::exists(out));
  }
  const auto run = run_cli("repair " + in + " -o " + out + " --weld 2");
  EXPECT_EQ(run.status, 2) << run.out;  // a usage error, as every number out of range
  EXPECT_NE(run.out.find("[0, 1]"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST(LimitsCli, ForeseeableAllocationBeyondAvailableMemoryFailsCleanly) {
  // With the limit lowered by the environment.
  TempDir d;
  const std::string in = d.file("m.ply"), out = d.file("o.ply");
  write_mesh(in, test::grid(20, 0.1));
  ::setenv("MSMESH_MEMORY_LIMIT", "100000", 1);
  const auto run = run_cli("denoise " + in + " -o " + out + " -q");
  ::unsetenv("MSMESH_MEMORY_LIMIT");
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find("needs about"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("MSMESH_MEMORY_LIMIT"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out));
}
