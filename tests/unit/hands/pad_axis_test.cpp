#include "azt/hands/pad_axis.hpp"

#include <gtest/gtest.h>

namespace azt::hands {
namespace {

// An Xbox-class pad's stick (xpad: −32768…32767, flat 128) and a cheap joystick's (0…255,
// flat 15), as their drivers report them in input_absinfo.
constexpr PadAxisRange kXpad{-32768, 32767, 128};
constexpr PadAxisRange kCheap{0, 255, 15};

TEST(PadDeflection, TheEndsAreFullDeflectionAndTheCentreIsNone) {
  EXPECT_DOUBLE_EQ(pad_deflection(32767, kXpad, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(pad_deflection(-32768, kXpad, 0.0), -1.0);
  EXPECT_DOUBLE_EQ(pad_deflection(0, kXpad, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(pad_deflection(255, kCheap, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(pad_deflection(0, kCheap, 0.0), -1.0);
}

TEST(PadDeflection, InsideTheDeadZoneIsZeroAndBeyondItStartsFromZero) {
  // Dead zone 0.1 of the half range: 0.1 → 0; 0.55 → (0.55 − 0.1) / 0.9 = 0.5.
  const double half = 32767.5;
  const auto at = [&](double x) { return static_cast<int>(-0.5 + x * half); };
  EXPECT_DOUBLE_EQ(pad_deflection(at(0.09), kXpad, 0.1), 0.0);
  EXPECT_NEAR(pad_deflection(at(0.55), kXpad, 0.1), 0.5, 1e-4);
  EXPECT_NEAR(pad_deflection(at(-0.55), kXpad, 0.1), -0.5, 1e-4);
  EXPECT_NEAR(pad_deflection(at(0.1001), kXpad, 0.1), 0.0, 1e-3);
}

TEST(PadDeflection, TheDriversFlatZoneCountsWhenItIsTheWider) {
  // The cheap stick's flat 15 of a half range of 127.5 is 0.118: wider than a 0.05 dead zone.
  EXPECT_DOUBLE_EQ(pad_deflection(140, kCheap, 0.05), 0.0);  // 0.098 from the centre
  EXPECT_GT(pad_deflection(150, kCheap, 0.05), 0.0);         // 0.176
}

TEST(PadDeflection, OutOfRangeValuesAreClampedAndADegenerateRangeIsNoDeflection) {
  EXPECT_DOUBLE_EQ(pad_deflection(99999, kCheap, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(pad_deflection(-99999, kCheap, 0.0), -1.0);
  EXPECT_DOUBLE_EQ(pad_deflection(5, PadAxisRange{5, 5, 0}, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(pad_deflection(5, PadAxisRange{10, 0, 0}, 0.0), 0.0);
}

}  // namespace
}  // namespace azt::hands
