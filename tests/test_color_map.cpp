// Colour maps (color_map.h).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <string>

#include "msmesh/color_map.h"
#include "msmesh/errors.h"

using namespace msmesh;

TEST(ColorMap, HeatEndsAndDistinctLabels) {
  EXPECT_TRUE(heat_color(0).isApprox(Eigen::Vector3d(1, 1, 204 / 255.0)));
  EXPECT_TRUE(heat_color(1).isApprox(Eigen::Vector3d(128, 0, 38) / 255.0));
  EXPECT_TRUE(heat_color(7).isApprox(heat_color(1)));
  EXPECT_FALSE(label_color(0).isApprox(label_color(1), 0.05));
}
