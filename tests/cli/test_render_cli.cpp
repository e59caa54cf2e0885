// `msmesh render`, `msmesh compare` and the --report pages of denoise, segment and inpaint.
// The rasteriser itself: test_render.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;
namespace fs = std::filesystem;

TEST(RenderCli, RenderCompareAndReport) {
  const fs::path dir = test::temp_folder("render_cli");
  const std::string M = std::string(MSMESH_CLI_PATH) + " ";
  auto q = [&](const char* name) { return "'" + (dir / name).string() + "'"; };
  ASSERT_EQ(test::run_command(M + "shape fandisk --resolution 4 -o " + q("clean.obj")).status, 0);
  ASSERT_EQ(test::run_command(M + "noise " + q("clean.obj") + " -o " + q("noisy.obj") + " --sigma 0.3 --seed 7").status,
            0);
  test::CliRun r =
      test::run_command(M + "denoise " + q("noisy.obj") + " -o " + q("den.obj") + " --truth " + q("clean.obj") +
                        " --save-field " + q("field.txt") + " --report " + q("report.html"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("report written to"), std::string::npos) << r.out;

  for (const std::string& args :
       std::vector<std::string>{"--color none --view front --size 120x90 --feature-edges 30",
                                "--color error --truth " + q("clean.obj") + " --size 200x150",
                                "--color field --field " + q("field.txt") + " --size 200x150 --perspective"}) {
    r = test::run_command(M + "render " + q("den.obj") + " -o " + q("r.png") + " " + args);
    ASSERT_EQ(r.status, 0) << args << "\n" << r.out;
    const std::string png = test::read_bytes(dir / "r.png");
    ASSERT_GT(png.size(), 100u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
  }
  r = test::run_command(M + "render " + q("den.obj") + " -o " + q("r.png") + " --color error");
  EXPECT_NE(r.status, 0) << "--color error without --truth must fail";
  r = test::run_command(M + "render " + q("den.obj") + " -o " + q("r.png") + " --size 12by3");
  EXPECT_NE(r.status, 0);

  r = test::run_command(M + "compare " + q("noisy.obj") + " " + q("den.obj") + " " + q("clean.obj") + " --truth " +
                        q("clean.obj") + " --captions 'noisy,denoised,truth' --size 150x120 --color error -o " +
                        q("sheet.png"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("denoised: MSAE"), std::string::npos) << r.out;
  const std::string sheet = test::read_bytes(dir / "sheet.png");
  ASSERT_GT(sheet.size(), 24u);
  auto be32 = [&](size_t i) {
    return (std::uint32_t(std::uint8_t(sheet[i])) << 24) | (std::uint32_t(std::uint8_t(sheet[i + 1])) << 16) |
           (std::uint32_t(std::uint8_t(sheet[i + 2])) << 8) | std::uint8_t(sheet[i + 3]);
  };
  EXPECT_GE(be32(16), 3u * 150u) << "three panels side by side";
  r = test::run_command(M + "compare " + q("noisy.obj") + " " + q("den.obj") + " --captions 'only one' -o " +
                        q("sheet.png"));
  EXPECT_NE(r.status, 0) << "captions must match the meshes";

  const std::string html = test::read_bytes(dir / "report.html");
  for (const char* part : {"<!DOCTYPE html>", "id=\"msmesh-data\"", "\"name\":\"input\"", "\"name\":\"result\"",
                           "\"name\":\"truth\"", "MSAE (x1e-3)", "<svg class=\"plot\"", "Three.js Authors"})
    EXPECT_NE(html.find(part), std::string::npos) << part;
  // Self-contained: nothing is loaded from elsewhere.
  for (const char* part : {"<script src", "<link", "@import", "url(http"})
    EXPECT_EQ(html.find(part), std::string::npos) << part;
  fs::remove_all(dir);
}

TEST(RenderCli, SegmentAndInpaintReports) {
  const fs::path dir = test::temp_folder("render_reports");
  const std::string M = std::string(MSMESH_CLI_PATH) + " ";
  auto q = [&](const char* name) { return "'" + (dir / name).string() + "'"; };
  ASSERT_EQ(test::run_command(M + "shape fandisk --resolution 6 -o " + q("clean.obj")).status, 0);
  test::CliRun r = test::run_command(M + "segment " + q("clean.obj") + " -o " + q("seg.ply") + " --labels " +
                                     q("labels.txt") + " --report " + q("seg.html") + " -q");
  ASSERT_EQ(r.status, 0) << r.out;
  std::string html = test::read_bytes(dir / "seg.html");
  for (const char* part : {"\"labels\":\"", "\"field\":\"", "\"initial_color\":\"labels\"", "<h2>Segments</h2>"})
    EXPECT_NE(html.find(part), std::string::npos) << part;
  r = test::run_command(M + "render " + q("clean.obj") + " --color labels --labels " + q("labels.txt") +
                        " --size 160x120 -o " + q("labels.png"));
  EXPECT_EQ(r.status, 0) << r.out;

  ASSERT_EQ(test::run_command(M + "holes " + q("clean.obj") + " -o " + q("holes.obj") + " --count 2 --seed 3").status,
            0);
  r = test::run_command(M + "inpaint " + q("holes.obj") + " -o " + q("filled.obj") + " --truth " + q("clean.obj") +
                        " --report " + q("inpaint.html") + " -q");
  ASSERT_EQ(r.status, 0) << r.out;
  html = test::read_bytes(dir / "inpaint.html");
  for (const char* part : {"\"highlight\":\"", "<h2>Holes</h2>", "Filled region against the ground truth"})
    EXPECT_NE(html.find(part), std::string::npos) << part;
  fs::remove_all(dir);
}
