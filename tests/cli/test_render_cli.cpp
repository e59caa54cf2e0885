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

TEST(RenderCli, UpAxisAndCameraAngles) {
  const fs::path dir = test::temp_folder("render_up");
  auto q = [&](const char* name) { return "'" + (dir / name).string() + "'"; };
  ASSERT_EQ(test::run_cli("shape fandisk --resolution 3 -o " + q("f.obj")).status, 0);
  auto render = [&](const std::string& args) {
    const test::CliRun r = test::run_cli("render " + q("f.obj") + " -o " + q("r.png") + " --size 90x70 " + args);
    EXPECT_EQ(r.status, 0) << args << "\n" << r.out;
    return std::make_pair(test::read_bytes(dir / "r.png"), r.out);
  };
  const auto y_up = render("");
  const auto z_up = render("--up z");
  EXPECT_NE(y_up.first, z_up.first) << "another up axis is another picture";
  EXPECT_NE(z_up.second.find("view iso, up z"), std::string::npos) << z_up.second;
  EXPECT_EQ(render("--up +z").first, z_up.first);
  EXPECT_NE(render("--up -z").first, z_up.first);
  const auto turned = render("--view front --azimuth 30 --elevation -20");
  EXPECT_NE(turned.second.find("view front, azimuth 30, elevation -20"), std::string::npos) << turned.second;
  EXPECT_NE(turned.first, render("--view front").first);
  EXPECT_EQ(render("--view front --azimuth 360").first.size() > 0, true);
  // Bad values are usage errors naming the option.
  for (const char* bad : {"--up w", "--azimuth 400", "--elevation 95", "--elevation x"}) {
    const test::CliRun r = test::run_cli("render " + q("f.obj") + " -o " + q("r.png") + " " + bad);
    EXPECT_EQ(r.status, 2) << bad << "\n" << r.out;
    EXPECT_NE(r.out.find(std::string(bad).substr(0, std::string(bad).find(' '))), std::string::npos) << r.out;
  }
  // compare takes the same camera options.
  const test::CliRun r =
      test::run_cli("compare " + q("f.obj") + " " + q("f.obj") + " --size 60x60 --up z --azimuth 45 -o " + q("s.png"));
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("view iso, up z, azimuth 45"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(RenderCli, TheFilesOwnColoursAreShown) {
  const fs::path dir = test::temp_folder("render_colors");
  auto q = [&](const char* name) { return "'" + (dir / name).string() + "'"; };
  Mesh m = make_cube(2);
  m.vertex_colors = Eigen::MatrixXd::Zero(m.V.rows(), 3);
  m.vertex_colors.col(0).setOnes();
  write_mesh((dir / "red.ply").string(), m);
  write_mesh((dir / "plain.ply").string(), make_cube(2));
  auto render = [&](const std::string& file, const std::string& args) {
    return test::run_cli("render " + q(file.c_str()) + " -o " + q("r.png") + " --size 60x60 " + args);
  };
  test::CliRun r = render("red.ply", "");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("colour file: the file's vertex colours"), std::string::npos) << r.out;
  const std::string coloured = test::read_bytes(dir / "r.png");
  r = render("red.ply", "--color none");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("colour none"), std::string::npos) << r.out;
  EXPECT_NE(test::read_bytes(dir / "r.png"), coloured);
  r = render("plain.ply", "");
  EXPECT_NE(r.out.find("colour none"), std::string::npos) << "auto without colours: grey\n" << r.out;
  r = render("plain.ply", "--color file");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("has no vertex colours"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(RenderCli, CompareErrorScaleComesFromTheResults) {
  const fs::path dir = test::temp_folder("compare_scale");
  auto q = [&](const char* name) { return "'" + (dir / name).string() + "'"; };
  ASSERT_EQ(test::run_cli("shape sphere --resolution 2 -o " + q("clean.obj")).status, 0);
  ASSERT_EQ(test::run_cli("noise " + q("clean.obj") + " -o " + q("noisy.obj") + " --sigma 0.4 --seed 2").status, 0);
  ASSERT_EQ(test::run_cli("noise " + q("clean.obj") + " -o " + q("result.obj") + " --sigma 0.03 --seed 2").status, 0);
  const std::string base = "compare " + q("noisy.obj") + " " + q("result.obj") + " " + q("clean.obj") + " --truth " +
                           q("clean.obj") + " --color error --size 100x100 -o " + q("s.png");
  auto top = [](const std::string& out) {
    const size_t at = out.find("error colours 0-");
    return at == std::string::npos ? -1.0 : std::stod(out.substr(at + 16));
  };
  test::CliRun r = test::run_cli(base);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("(the noisy input)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scale from the results; the noisy input saturates"), std::string::npos) << r.out;
  const double from_results = top(r.out);
  r = test::run_cli(base + " --noisy-panel none");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("scale from all panels"), std::string::npos) << r.out;
  const double from_all = top(r.out);
  EXPECT_GT(from_results, 0);
  EXPECT_GT(from_all, 2 * from_results) << r.out;
  r = test::run_cli(base + " --noisy-panel 1");
  EXPECT_EQ(top(r.out), from_results) << r.out;
  r = test::run_cli(base + " --noisy-panel 4");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--noisy-panel"), std::string::npos) << r.out;
  fs::remove_all(dir);
}
