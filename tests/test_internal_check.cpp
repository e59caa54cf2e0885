// The range checks the options' validate() share (src/check.h).
#include <gtest/gtest.h>

#include <cmath>
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
  using detail::Ends;
  EXPECT_EQ(message([] { detail::check_positive("stage", "alpha", -1); }),
            "stage: alpha = -1 is out of range; valid: > 0");
  EXPECT_EQ(message([] { detail::check_non_negative("stage", "sigma", -2, "(note)"); }),
            "stage: sigma = -2 is out of range; valid: >= 0 (note)");
  EXPECT_EQ(message([] { detail::check_range("stage", "k", 0, 1, 100, Ends::Closed); }),
            "stage: k = 0 is out of range; valid: [1, 100]");
  EXPECT_EQ(message([] { detail::check_range("stage", "t", 1, 0, 1, Ends::ClosedOpen); }),
            "stage: t = 1 is out of range; valid: [0, 1)");
  EXPECT_EQ(message([] { detail::check_range("stage", "t", 0, 0, 1, Ends::OpenClosed); }),
            "stage: t = 0 is out of range; valid: (0, 1]");
  EXPECT_NE(message([] { detail::check_range("stage", "t", std::nan(""), 0, 1, Ends::Closed); }), "");
  EXPECT_EQ(message([] { detail::check_range("stage", "t", 1, 0, 1, Ends::Closed); }), "");
  EXPECT_EQ(message([] { detail::check_positive("stage", "t", 1e-300); }), "");
}
