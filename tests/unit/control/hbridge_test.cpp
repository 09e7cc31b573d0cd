// The IBT-2 H-bridge layer (docs/hardware.md): never reversed under load.
#include "azt/control/hbridge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace azt::control {
namespace {

TEST(HBridge, DrivesOneSideAtATime) {
  HBridge b(0.1);
  const auto up = b.drive(0.0, 0.6);
  EXPECT_DOUBLE_EQ(up.rpwm, 0.6);
  EXPECT_DOUBLE_EQ(up.lpwm, 0.0);
  EXPECT_TRUE(up.enable);
  const auto clamped = b.drive(0.01, 7.0);
  EXPECT_DOUBLE_EQ(clamped.rpwm, 1.0);
}

TEST(HBridge, AReversalWaitsTheDeadTimeWithBothSidesOff) {
  HBridge b(0.1);
  b.drive(0.0, 0.8);
  for (double t = 0.01; t < 0.105; t += 0.01) {
    const auto o = b.drive(t, -0.8);
    EXPECT_DOUBLE_EQ(o.rpwm, 0.0) << t;
    EXPECT_DOUBLE_EQ(o.lpwm, 0.0) << t;
  }
  EXPECT_DOUBLE_EQ(b.drive(0.12, -0.8).lpwm, 0.8);
}

TEST(HBridge, TheSameSideRestartsAtOnceAfterAPause) {
  HBridge b(0.1);
  b.drive(0.0, 0.5);
  b.drive(0.05, 0.0);
  EXPECT_DOUBLE_EQ(b.drive(0.06, 0.5).rpwm, 0.5);
}

TEST(HBridge, NotANumberDisablesAndTheNextDriveWaits) {
  HBridge b(0.1);
  b.drive(0.0, 0.5);
  const auto off = b.drive(0.01, std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(off.enable);
  EXPECT_DOUBLE_EQ(off.rpwm + off.lpwm, 0.0);
  EXPECT_DOUBLE_EQ(b.drive(0.05, -0.5).lpwm, 0.0);  // the other way: dead time from the disable
  EXPECT_DOUBLE_EQ(b.drive(0.12, -0.5).lpwm, 0.5);
}

// Random duties (signs, zeros, NaN) at random instants: never both sides, and never a side
// driven less than the dead time after the other side was.
TEST(HBridge, RandomDutiesNeverReverseUnderLoad) {
  HBridge b(0.05);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> duty(-1.2, 1.2);
  std::uniform_real_distribution<double> step(0.0005, 0.03);
  std::uniform_int_distribution<int> special(0, 19);
  double t = 0.0;
  double last_r = -1.0;  // when each side was last driven
  double last_l = -1.0;
  int violations = 0;
  for (int i = 0; i < 100000; ++i) {
    t += step(rng);
    const int s = special(rng);
    const double d = s == 0 ? 0.0 : (s == 1 ? std::nan("") : duty(rng));
    const auto o = b.drive(t, d);
    violations += (o.rpwm > 0.0 && o.lpwm > 0.0) ? 1 : 0;
    if (o.rpwm > 0.0) {
      violations += (last_l >= 0.0 && t - last_l < 0.05 - 1e-12) ? 1 : 0;
      last_r = t;
    }
    if (o.lpwm > 0.0) {
      violations += (last_r >= 0.0 && t - last_r < 0.05 - 1e-12) ? 1 : 0;
      last_l = t;
    }
  }
  EXPECT_EQ(violations, 0);
  EXPECT_GT(last_r, 0.0);
  EXPECT_GT(last_l, 0.0);
}

}  // namespace
}  // namespace azt::control
