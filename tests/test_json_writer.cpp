// json_writer.h: ordered objects, escaping, numbers (non-finite as null), arrays and nesting.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "msmesh/json_writer.h"

using namespace msmesh;

TEST(JsonWriter, OrderedObjectsWithEveryKindOfValue) {
  Json inner;
  inner.add("x", 1);
  Json j;
  j.add("name", "a \"quoted\"\n\\ name")
      .add("count", 3LL)
      .add("ratio", 0.25)
      .add("ok", true)
      .add("list", std::vector<double>{1.5, 2})
      .add("ints", std::vector<int>{4, 5})
      .add("inner", inner)
      .add("objects", std::vector<Json>{inner, inner})
      .raw("none", "null");
  EXPECT_EQ(j.str(),
            "{\"name\":\"a \\\"quoted\\\"\\n\\\\ name\",\"count\":3,\"ratio\":0.25,\"ok\":true,\"list\":[1.5,2],"
            "\"ints\":[4,5],\"inner\":{\"x\":1},\"objects\":[{\"x\":1},{\"x\":1}],\"none\":null}");
}

TEST(JsonWriter, NonFiniteNumbersAndControlCharacters) {
  EXPECT_EQ(Json::number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(Json::number(std::numeric_limits<double>::infinity()), "null");
  EXPECT_EQ(Json::number(1.0 / 3.0), "0.3333333333");
  EXPECT_EQ(Json::quote(std::string("a\x01") + "\t"), "\"a\\u0001\\t\"");
  EXPECT_EQ(Json().str(), "{}");
}
