#include "azt/hands/debounced_input.hpp"

#include <gtest/gtest.h>

namespace azt::hands {
namespace {

TEST(DebouncedInput, APressIsBelievedOnlyAfterItHeldForTheSettlingTime) {
  DebouncedInput button(0.03);
  EXPECT_FALSE(button.update(1.000, true));
  EXPECT_FALSE(button.update(1.020, true));
  EXPECT_TRUE(button.update(1.030, true));
  EXPECT_TRUE(button.update(1.500, true));
}

TEST(DebouncedInput, ContactBounceShorterThanTheSettlingTimeChangesNothing) {
  DebouncedInput button(0.03);
  // A release that bounces: the contact opens and closes every 5 ms for 20 ms, then stays shut.
  button.update(0.0, true);
  ASSERT_TRUE(button.update(0.1, true));
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(button.update(0.200 + 0.010 * i, false));
    EXPECT_TRUE(button.update(0.205 + 0.010 * i, true));
  }
  EXPECT_TRUE(button.update(0.5, true));
}

TEST(DebouncedInput, AReleaseSettlesTheSameWay) {
  DebouncedInput button(0.03);
  button.update(0.0, true);
  button.update(0.05, true);
  EXPECT_TRUE(button.update(1.00, false));
  EXPECT_TRUE(button.update(1.02, true));  // bounced back: the clock starts again
  EXPECT_TRUE(button.update(1.04, false));
  EXPECT_TRUE(button.update(1.06, false));
  EXPECT_FALSE(button.update(1.07, false));
  EXPECT_FALSE(button.level());
}

TEST(DebouncedInput, ZeroSettlingFollowsTheRawLevel) {
  DebouncedInput button(0.0);
  EXPECT_TRUE(button.update(0.0, true));
  EXPECT_FALSE(button.update(0.0, false));
}

}  // namespace
}  // namespace azt::hands
