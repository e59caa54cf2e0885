// compare_sheet.h: panels side by side, shared framing, error figures and an error scale taken
// from the results rather than the noisy input.
#include <gtest/gtest.h>

#include "image_test_helpers.h"
#include "msmesh/color_map.h"
#include "msmesh/compare_sheet.h"
#include "msmesh/errors.h"
#include "msmesh/noise.h"
#include "msmesh/shapes.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

/// The truth, a lightly noisy "result" and a very noisy "input" of the same sphere.
struct Trio {
  Mesh truth, result, input;
};
Trio trio() {
  Trio t;
  t.truth = make_sphere(2);
  t.result = t.input = t.truth;
  NoiseOptions no;
  no.seed = 3;
  no.sigma = 0.02;
  t.result.V = add_noise(t.truth.V, t.truth.F, no);
  no.sigma = 0.4;
  t.input.V = add_noise(t.truth.V, t.truth.F, no);
  return t;
}

ComparePanel panel(const Mesh& m, const std::string& caption) { return {m.V, m.F, m.vertex_colors, caption}; }

}  // namespace

TEST(CompareSheet, AutoNoisyPanelNeedsAClearlyWorstPanel) {
  EXPECT_EQ(auto_noisy_panel({20, 3, 0}), 0);
  EXPECT_EQ(auto_noisy_panel({3, 20}), 1);
  EXPECT_EQ(auto_noisy_panel({5, 4}), -1) << "not twice as bad";
  EXPECT_EQ(auto_noisy_panel({5}), -1) << "one panel";
  EXPECT_EQ(auto_noisy_panel({-1, -1}), -1) << "no errors";
}

TEST(CompareSheet, ScaleLeavesOutTheNoisyPanelAndTheTruth) {
  const std::vector<Eigen::VectorXd> a = {Eigen::VectorXd::Constant(10, 40), Eigen::VectorXd::Constant(10, 1.5),
                                          Eigen::VectorXd::Zero(10)};
  EXPECT_DOUBLE_EQ(sheet_error_scale(a, 0, 0), 2.0);
  EXPECT_DOUBLE_EQ(sheet_error_scale(a, -1, 0), 50.0) << "all panels pooled";
  EXPECT_DOUBLE_EQ(sheet_error_scale(a, 0, 7), 7.0) << "set by hand";
  EXPECT_DOUBLE_EQ(sheet_error_scale({a[0], a[2]}, 0, 0), 50.0) << "nothing else with errors: all panels";
}

TEST(CompareSheet, ErrorColorsOfTheResultsAreNotWashedOut) {
  const Trio t = trio();
  CompareOptions o;
  o.render.width = o.render.height = 120;
  o.color = SheetColor::Error;
  const std::vector<ComparePanel> panels = {panel(t.input, "noisy"), panel(t.result, "result"),
                                            panel(t.truth, "truth")};
  const CompareSheet s = compare_sheet(panels, t.truth.V, t.truth.F, o);
  ASSERT_EQ(s.evaluations.size(), 3u);
  EXPECT_EQ(s.noisy_panel, 0);
  EXPECT_TRUE(s.saturated);
  EXPECT_NE(s.scale_note.find("noisy input saturates"), std::string::npos) << s.scale_note;
  // The scale follows the result's errors, far below the input's.
  const double result_mean = s.evaluations[1].normals.mean_angle_deg;
  EXPECT_LT(s.error_top, 4 * result_mean + 1);
  EXPECT_GT(s.error_top, result_mean);
  EXPECT_LT(s.error_top, s.evaluations[0].normals.mean_angle_deg);
  // Without leaving the input out, the scale grows to its errors.
  o.noisy_panel = kNoNoisyPanel;
  const CompareSheet all = compare_sheet(panels, t.truth.V, t.truth.F, o);
  EXPECT_EQ(all.noisy_panel, -1);
  EXPECT_GT(all.error_top, 2 * s.error_top);
  EXPECT_GT(s.image.height, all.image.height) << "the noisy panel's saturation line";
  // An explicit panel.
  o.noisy_panel = 1;
  EXPECT_EQ(compare_sheet(panels, t.truth.V, t.truth.F, o).noisy_panel, 1);
  o.noisy_panel = 3;
  EXPECT_THROW(compare_sheet(panels, t.truth.V, t.truth.F, o), InvalidInput);
}

TEST(CompareSheet, LayoutAndColors) {
  const Trio t = trio();
  CompareOptions o;
  o.render.width = 100;
  o.render.height = 80;
  Mesh coloured = t.truth;
  coloured.vertex_colors = Eigen::MatrixXd::Zero(coloured.V.rows(), 3);
  coloured.vertex_colors.col(0).setOnes();  // red
  const CompareSheet s = compare_sheet({panel(t.truth, "grey"), panel(coloured, "red")}, {}, {}, o);
  EXPECT_GE(s.image.width, 200);
  EXPECT_TRUE(s.evaluations.empty());
  // Auto colours: the second panel is red, the first grey (centre pixels of each picture).
  const auto grey = test::px(s.image, 8 + 50, 6 + 40);
  const auto red = test::px(s.image, 8 + 100 + 8 + 50, 6 + 40);
  EXPECT_LE(std::abs(grey[0] - grey[1]), 2);
  EXPECT_GT(red[0], red[1] + 60);
  o.color = SheetColor::None;
  const auto plain = test::px(compare_sheet({panel(t.truth, "grey"), panel(coloured, "red")}, {}, {}, o).image,
                              8 + 100 + 8 + 50, 6 + 40);
  EXPECT_LE(std::abs(plain[0] - plain[1]), 2);
  o.color = SheetColor::Error;
  EXPECT_THROW(compare_sheet({panel(t.truth, "a")}, {}, {}, o), InvalidInput) << "error colours need a truth";
  EXPECT_THROW(compare_sheet({}, {}, {}, CompareOptions{}), InvalidInput);
  EXPECT_EQ(sheet_color_from_name("file"), SheetColor::File);
  EXPECT_THROW(sheet_color_from_name("rainbow"), InvalidInput);
}
