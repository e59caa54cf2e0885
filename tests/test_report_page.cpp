// report_page.h: the self-contained HTML report (viewer data, tables, parameters, plots,
// notes), escaping, and the checks of the viewer's per-mesh arrays. The pages of the CLI's
// --report options: cli/test_render_cli.cpp; in a browser: tests/browser.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/report_page.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

ReportData sample() {
  const Mesh g = test::grid(3);
  ReportData d;
  d.title = "title <with> & tags";
  d.subtitle = "a subtitle";
  ReportMesh m{"result", g.V, g.F, Eigen::VectorXd::Constant(g.F.rows(), 2.0), {}, {}, {}};
  m.edge_field = Eigen::VectorXd::Ones(build_topology(g.F, g.V.rows()).num_edges());
  m.face_labels = Eigen::VectorXi::Zero(g.F.rows());
  m.highlighted_faces.assign(static_cast<size_t>(g.F.rows()), false);
  d.meshes.push_back(m);
  d.meshes.push_back({"truth", g.V, g.F, {}, {}, {}, {}});
  d.initial_color = "error";
  d.parameters.push_back({"alpha", "2.5"});
  d.tables.push_back({"Errors", ReportTable{{"mesh", "MSAE"}, {{"result", "1.5"}}}});
  d.plots.push_back({"Residual", "value", true, {{"residual", {1.0, 0.1, 0.01}}}});
  d.notes.push_back("a note");
  return d;
}

}  // namespace

TEST(ReportPage, SelfContainedPageWithEverySection) {
  const std::string html = report_html(sample());
  for (const char* part :
       {"<!DOCTYPE html>", "title &lt;with&gt; &amp; tags", "a subtitle", "id=\"msmesh-data\"", "\"name\":\"result\"",
        "\"name\":\"truth\"", "\"indices_of\":0", "\"error\":\"", "\"field\":\"", "\"labels\":\"", "\"highlight\":\"",
        "\"initial_color\":\"error\"", "<h2>Errors</h2>", "<h2>Parameters</h2>", "alpha", "<svg class=\"plot\"",
        "a note", "Three.js Authors"})
    EXPECT_NE(html.find(part), std::string::npos) << part;
  for (const char* part : {"<script src", "<link", "@import", "url(http"})
    EXPECT_EQ(html.find(part), std::string::npos) << part;
  EXPECT_FALSE(report_viewer_script().empty());
}

TEST(ReportPage, WithoutMeshesThereIsNoViewer) {
  ReportData d = sample();
  d.meshes.clear();
  const std::string html = report_html(d);
  EXPECT_EQ(html.find("id=\"msmesh-data\""), std::string::npos);
  EXPECT_NE(html.find("<h2>Errors</h2>"), std::string::npos);
}

TEST(ReportPage, ArraysOfTheWrongSizeAreRefused) {
  for (int which = 0; which < 4; ++which) {
    ReportData d = sample();
    ReportMesh& m = d.meshes[0];
    if (which == 0) m.face_error_deg = Eigen::VectorXd::Zero(2);
    if (which == 1) m.edge_field = Eigen::VectorXd::Zero(2);
    if (which == 2) m.face_labels = Eigen::VectorXi::Zero(2);
    if (which == 3) m.highlighted_faces.assign(2, true);
    EXPECT_THROW(report_html(d), InvalidInput) << which;
  }
  ReportData d = sample();
  d.meshes[0].F(0, 0) = 999;
  EXPECT_THROW(report_html(d), InvalidInput);
}

TEST(ReportPage, WriteReportWritesTheFile) {
  const std::filesystem::path dir = test::temp_folder("report_page");
  const std::string path = (dir / "r.html").string();
  write_report(path, sample());
  EXPECT_EQ(test::read_bytes(path), report_html(sample()));
  EXPECT_THROW(write_report((dir / "no" / "r.html").string(), sample()), IoError);
  std::filesystem::remove_all(dir);
}
