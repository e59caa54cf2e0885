// `msmesh repair`: the summary lines, --dry-run --json, a file whose every face goes, and a
// missing -o. The library's repair_mesh: test_repair.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"
#include "msmesh/topology.h"

using namespace msmesh;
using msmesh::test::run_cli;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;
namespace fs = std::filesystem;

TEST(Repair, CliSummaryJsonAndErrors) {
  TempDir d;
  const std::string in = d.file("messy.obj"), out = d.file("fixed.ply");
  write_bytes(in,
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\n"
              "f 1 2 3\nf 5 3 4\nf 1 2 3\nf 1 1 2\n");
  auto run = run_cli("repair " + in + " -o " + out);
  ASSERT_EQ(run.status, 0) << run.out;
  for (const char* line :
       {"dropped on reading, faces repeating a vertex: 1", "merged duplicate vertices: 1", "removed duplicate faces: 1",
        "flipped faces to orient components consistently: 1", "remaining: 1 components", "--remove-unreferenced"})
    EXPECT_NE(run.out.find(line), std::string::npos) << line << "\n" << run.out;
  const Mesh fixed = read_mesh(out);
  EXPECT_EQ(fixed.V.rows(), 5);
  EXPECT_EQ(fixed.F.rows(), 2);
  EXPECT_EQ(summarize_topology(fixed.F, build_topology(fixed.F, 5)).inconsistently_oriented_edges, 0);
  run = run_cli("repair " + in + " --dry-run --json --remove-unreferenced");
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_NE(run.out.find("\"vertices_after\":4"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"unreferenced_vertices_removed\":1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"faces_after\":2"), std::string::npos) << run.out;
  // A file whose every face goes: error, nothing written.
  const std::string all_dup = d.file("flat.obj"), out2 = d.file("flat_out.obj");
  write_bytes(all_dup, "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  run = run_cli("repair " + all_dup + " -o " + out2);
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find(all_dup + ": repair removed every face"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out2));
  run = run_cli("repair " + in);
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find("--dry-run"), std::string::npos) << run.out;
}
