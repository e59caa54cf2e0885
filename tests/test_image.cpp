// Images (image.h): panels side by side and stacked.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <string>

#include "image_test_helpers.h"
#include "msmesh/errors.h"
#include "msmesh/image.h"

using namespace msmesh;

TEST(Image, Stacks) {
  const Image a(10, 5, Eigen::Vector3d(1, 0, 0)), b(4, 8, Eigen::Vector3d(0, 0, 1));
  const Image h = hstack({a, b}, 2);
  EXPECT_EQ(h.width, 16);
  EXPECT_EQ(h.height, 8);
  EXPECT_EQ(test::px(h, 0, 0), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(test::px(h, 11, 0), (std::array<int, 3>{255, 255, 255}));
  EXPECT_EQ(test::px(h, 12, 7), (std::array<int, 3>{0, 0, 255}));
  const Image v = vstack({a, b}, 1);
  EXPECT_EQ(v.width, 10);
  EXPECT_EQ(v.height, 14);
}
