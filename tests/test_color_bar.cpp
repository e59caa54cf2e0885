// Colour bars (color_bar.h): tick labels and the bar.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <string>

#include "image_test_helpers.h"
#include "msmesh/color_bar.h"
#include "msmesh/color_map.h"
#include "msmesh/errors.h"
#include "msmesh/image.h"

using namespace msmesh;

TEST(ColorBar, TickLabels) {
  EXPECT_EQ(format_tick(0), "0");
  EXPECT_EQ(format_tick(0.25), "0.25");
  EXPECT_EQ(format_tick(12.5), "12.5");
  EXPECT_EQ(format_tick(1500), "1500");
  EXPECT_EQ(format_tick(100), "100");
  EXPECT_EQ(format_tick(0.6789), "0.679");
  EXPECT_EQ(format_tick(-2), "-2");
  EXPECT_EQ(format_tick(2e-5), "2e-05");
}

TEST(ColorBar, ShowsTheMapFromLeftToRight) {
  Image im(300, 40);
  ColorBar bar;
  bar.map = heat_color;
  bar.min = 0;
  bar.max = 10;
  draw_color_bar(im, 0, 0, 300, 40, bar, 1);
  // Somewhere in the bar's first row the lightest colour, further right darker ones.
  const auto left = test::px(im, 20, 5), right = test::px(im, 280, 5);
  EXPECT_GT(left[1], right[1] + 100);
  EXPECT_THROW(draw_color_bar(im, 0, 0, 10, 10, ColorBar{}, 1), InvalidInput);
}
