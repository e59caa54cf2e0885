// The range checks of the options without a parameter table (src/check.h).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "check.h"
#include "msmesh/errors.h"

using namespace msmesh;

TEST(InternalCheck, MessagesNameParameterValueAndRange) {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message([] { detail::check_positive("stage", "alpha", -1); }),
            "stage: alpha = -1 is out of range; valid: > 0");
  EXPECT_EQ(message([] { detail::check_non_negative("stage", "sigma", -2); }),
            "stage: sigma = -2 is out of range; valid: >= 0");
  EXPECT_EQ(message([] {
              detail::check_range("stage", "k", 0, {1, 100});
            }),
            "stage: k = 0 is out of range; valid: in [1, 100]");
  EXPECT_EQ(message([] {
              detail::check_range("stage", "t", 1, {0, 1, false, true});
            }),
            "stage: t = 1 is out of range; valid: in [0, 1)");
  EXPECT_EQ(message([] {
              detail::check_range("stage", "t", 0, {0, 1, true, false});
            }),
            "stage: t = 0 is out of range; valid: in (0, 1]");
  EXPECT_NE(message([] { detail::check_range("stage", "t", std::nan(""), {0, 1}); }), "");
  EXPECT_NE(message([] { detail::check_non_negative("stage", "t", std::numeric_limits<double>::infinity()); }), "");
  EXPECT_EQ(message([] { detail::check_range("stage", "t", 1, {0, 1}); }), "");
  EXPECT_EQ(message([] { detail::check_positive("stage", "t", 1e-300); }), "");
}
