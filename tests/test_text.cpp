// Text (text.h): the bitmap font.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>
#include <string>

#include "image_test_helpers.h"
#include "msmesh/errors.h"
#include "msmesh/image.h"
#include "msmesh/text.h"

using namespace msmesh;

TEST(Text, StaysInItsBox) {
  Image im(60, 30);
  EXPECT_EQ(text_width("ab", 2), 22);
  EXPECT_EQ(text_height(2), 16);
  EXPECT_EQ(text_width("5\xC2\xB0", 1), 11) << "the degree sign is one character";
  draw_text(im, 10, 5, "E8", Eigen::Vector3d::Zero(), 2);
  int inside = 0, outside = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const bool ink = test::px(im, x, y)[0] == 0;
      const bool in_box = x >= 10 && x < 10 + text_width("E8", 2) && y >= 5 && y < 5 + text_height(2);
      (in_box ? inside : outside) += ink;
    }
  EXPECT_GT(inside, 40);
  EXPECT_EQ(outside, 0);
}
