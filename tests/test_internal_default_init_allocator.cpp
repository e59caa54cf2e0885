// default_init_allocator.h (internal): vectors whose resize leaves new numbers unset, for arrays
// that a parallel pass writes in full. Apart from that they are ordinary vectors: what was there
// stays, explicit values are set, copies and element types other than numbers work.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "default_init_allocator.h"

using namespace msmesh;

TEST(DefaultInitAllocator, KeepsWhatWasThereAndSetsExplicitValues) {
  detail::UninitializedVector<double> v(3, 2.5);  // an explicit value is set
  EXPECT_EQ(v, (detail::UninitializedVector<double>{2.5, 2.5, 2.5}));
  v[1] = -1;
  v.resize(1000);  // grows: the old entries move along
  ASSERT_EQ(v.size(), 1000u);
  EXPECT_EQ(v[0], 2.5);
  EXPECT_EQ(v[1], -1.0);
  EXPECT_EQ(v[2], 2.5);
  v.resize(2);
  v.resize(5, 7.0);  // resize with a value sets the new ones
  EXPECT_EQ(v[4], 7.0);
  v.assign(4, 0.0);
  EXPECT_EQ(v, (detail::UninitializedVector<double>(4, 0.0)));
  const detail::UninitializedVector<double> copy = v;
  EXPECT_EQ(copy, v);
}

TEST(DefaultInitAllocator, HoldsRowsAndClasses) {
  detail::UninitializedVector<std::array<int, 4>> quads(2);
  quads[0] = {1, 2, 3, 4};
  quads.push_back({5, 6, 7, 8});
  EXPECT_EQ(quads.size(), 3u);
  EXPECT_EQ(quads[2][3], 8);
  // A class is still constructed (default-initialisation runs its constructor).
  detail::UninitializedVector<std::string> names(2);
  EXPECT_TRUE(names[0].empty());
  names.emplace_back("x");
  EXPECT_EQ(names.back(), "x");
}
