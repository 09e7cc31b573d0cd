// The movement-window controller on its own, tick by tick (closed-loop behaviour against the
// simulated plant is in station_sim_test.cpp). Seed 000, "AnTrack Antenna Movement Window".
#include "azt/control/axis_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::control {
namespace {

constexpr double kTick = 0.05;
constexpr double kLsb12 = 360.0 / 4096.0;  // seed appendix: 12 bits, 0.0879°

AxisControlConfig config(double window_deg) {
  AxisControlConfig c;
  c.window_deg = window_deg;
  c.lsb_deg = kLsb12;
  c.max_rate_deg_s = 1.5;
  c.ramp_s = 1.0;
  c.min_duty = 0.1;
  c.time_constant_s = 0.3;
  return c;
}

TEST(AxisControlConfig, Validates) {
  EXPECT_TRUE(AxisControlConfig::make(config(0.0)).ok());
  EXPECT_TRUE(AxisControlConfig::make(config(2.0)).ok());
  EXPECT_FALSE(AxisControlConfig::make(config(2.1)).ok());  // seed: window 0.0–2.0°
  auto c = config(0.1);
  c.tracking_speed = 0.0;
  EXPECT_FALSE(AxisControlConfig::make(c).ok());
  c = config(0.1);
  c.min_duty = 0.95;
  EXPECT_FALSE(AxisControlConfig::make(c).ok());
  c = config(0.1);
  c.lsb_deg = std::nan("");
  EXPECT_FALSE(AxisControlConfig::make(c).ok());
}

TEST(AxisController, DoesNotMoveInsideL2) {
  // L2 = window + 1 LSB; "a window of 0 still has a 1-bitDegree hysteresis window".
  for (double window : {0.0, 0.5}) {
    AxisController ctl(config(window));
    const double l2 = window + kLsb12;
    EXPECT_EQ(ctl.update(100.0 + 0.999 * l2, 100.0, 0.0, kTick), 0.0);
    EXPECT_EQ(ctl.update(100.0 - 0.999 * l2, 100.0, 0.0, kTick), 0.0);
    EXPECT_EQ(ctl.starts(), 0u);
    EXPECT_GT(ctl.update(100.0 + 1.001 * l2, 100.0, 0.0, kTick), 0.0);
    EXPECT_TRUE(ctl.moving());
    EXPECT_EQ(ctl.starts(), 1u);
  }
}

TEST(AxisController, SoftStartLimitsTheDutySlope) {
  AxisController ctl(config(0.0));
  double previous = 0.0;
  for (int k = 0; k < 40; ++k) {
    const double duty = ctl.update(200.0, 100.0, 0.0, kTick);
    EXPECT_LE(duty - previous, kTick / 1.0 + 1e-12);  // ramp_s = 1 s from 0 to full duty
    previous = duty;
  }
  EXPECT_NEAR(previous, 1.0, 1e-9);  // far beyond L1 = 3°: full speed
}

TEST(AxisController, TrackingSpeedInsideThreeDegrees) {
  AxisController ctl(config(0.0));
  double duty = 0.0;
  for (int k = 0; k < 40; ++k) duty = ctl.update(102.0, 100.0, 0.0, kTick);
  // Half speed (the default tracking speed) after stiction compensation: 0.1 + 0.9·0.5.
  EXPECT_NEAR(duty, 0.55, 1e-9);
}

TEST(AxisController, DeceleratesNearTheGoalAndStopsWithinOneLsb) {
  AxisController ctl(config(0.0));
  double duty = 0.0;
  for (int k = 0; k < 40; ++k) duty = ctl.update(100.1, 100.0, 0.0, kTick);
  // 0.1° away: K·d with K = 1/(4τ) = 0.8333/s gives 0.08333°/s; after stiction compensation
  // (min duty 0.1 plus the rest in proportion to 1.5°/s) the duty is 0.15.
  EXPECT_NEAR(duty, 0.15, 1e-9);
  EXPECT_EQ(ctl.update(100.1, 100.1 - 0.9 * kLsb12, 0.0, kTick), 0.0);
  EXPECT_FALSE(ctl.moving());
}

TEST(AxisController, MovesTheOtherWayForNegativeErrors) {
  AxisController ctl(config(0.0));
  double duty = 0.0;
  for (int k = 0; k < 40; ++k) duty = ctl.update(90.0, 100.0, 0.0, kTick);
  EXPECT_NEAR(duty, -1.0, 1e-9);
}

TEST(AxisController, LeadsAMovingTargetByTheWindow) {
  AxisController ctl(config(0.5));
  const double rate = 15.0 / 3600.0;  // the Moon in azimuth
  ASSERT_GT(ctl.update(100.0 + 0.6, 100.0, rate, kTick), 0.0);
  // The goal is the target plus the window in the direction it moves: still short of it here …
  EXPECT_GT(ctl.update(100.6, 100.9, rate, kTick), 0.0);
  // … still moving half a count short of target + 0.5° (a led goal is reached or passed) …
  EXPECT_GT(ctl.update(100.6, 101.1 - 0.5 * kLsb12, rate, kTick), 0.0);
  // … and arrived once the reading gets there.
  EXPECT_EQ(ctl.update(100.6, 101.1 + 0.1 * kLsb12, rate, kTick), 0.0);
  EXPECT_FALSE(ctl.moving());
}

TEST(AxisController, HaltDropsTheDutyAtOnce) {
  AxisController ctl(config(0.0));
  for (int k = 0; k < 40; ++k) ctl.update(200.0, 100.0, 0.0, kTick);
  ctl.halt();
  EXPECT_EQ(ctl.duty(), 0.0);
  EXPECT_FALSE(ctl.moving());
}

TEST(AxisController, NonFiniteInputsHalt) {
  AxisController ctl(config(0.0));
  for (int k = 0; k < 10; ++k) ctl.update(200.0, 100.0, 0.0, kTick);
  EXPECT_EQ(ctl.update(std::nan(""), 100.0, 0.0, kTick), 0.0);
  EXPECT_EQ(ctl.update(200.0, INFINITY, 0.0, kTick), 0.0);
  EXPECT_EQ(ctl.update(200.0, 100.0, 0.0, 0.0), 0.0);
}

}  // namespace
}  // namespace azt::control
