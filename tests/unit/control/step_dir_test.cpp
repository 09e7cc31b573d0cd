// The step/direction drive (control/step_dir.hpp): the rate a stepper can follow, DIR changed
// only at a standstill with a tick of set-up, a bad number stopping it.
#include "azt/control/step_dir.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace azt::control {
namespace {

constexpr double kTickS = 0.05;
const StepDirConfig kConfig{2000.0, 200.0, 4000.0};

TEST(StepDir, AStartSetsDirFirstThenStepsAtThePullInRateThenRamps) {
  StepDir d(kConfig);
  const StepDirOutputs first = d.drive(0.0, 1.0);
  EXPECT_EQ(first.direction, 1);
  EXPECT_EQ(first.step_hz, 0.0);  // the driver's DIR set-up: no step this tick
  EXPECT_TRUE(first.enable);
  EXPECT_DOUBLE_EQ(d.drive(kTickS, 1.0).step_hz, 200.0);
  // 4000 Hz/s: 200 more a tick, so full rate after nine more ticks, not sooner.
  double hz = 0.0;
  for (int i = 2; i <= 10; ++i) hz = d.drive(i * kTickS, 1.0).step_hz;
  EXPECT_NEAR(hz, 2000.0, 1e-6);
  StepDir early(kConfig);
  for (int i = 0; i <= 9; ++i) hz = early.drive(i * kTickS, 1.0).step_hz;
  EXPECT_NEAR(hz, 1800.0, 1e-6);
}

TEST(StepDir, InsideThePullInBandTheRateFollowsAtOnce) {
  StepDir d(kConfig);
  (void)d.drive(0.0, 0.05);
  EXPECT_DOUBLE_EQ(d.drive(kTickS, 0.05).step_hz, 100.0);
  EXPECT_DOUBLE_EQ(d.drive(2 * kTickS, 0.02).step_hz, 40.0);
  EXPECT_DOUBLE_EQ(d.drive(3 * kTickS, 0.0).step_hz, 0.0);
  // Slower than a pulse a second: none (the PWM makes no longer period).
  EXPECT_DOUBLE_EQ(d.drive(4 * kTickS, 0.0004).step_hz, 0.0);
}

TEST(StepDir, AReversalRampsDownStopsTurnsDirAndRampsUp) {
  StepDir d(kConfig);
  double t = 0.0;
  for (int i = 0; i < 20; ++i) (void)d.drive(t = i * kTickS, 1.0);
  t += kTickS;
  ASSERT_NEAR(d.drive(t, 1.0).step_hz, 2000.0, 1e-6);
  int ticks_down = 0;
  StepDirOutputs o;
  for (o = d.drive(t += kTickS, -1.0); o.direction == 1; o = d.drive(t += kTickS, -1.0)) {
    ++ticks_down;
    ASSERT_LT(ticks_down, 100);
  }
  // 2000 → 200 at 200 a tick is nine ticks; from the band's edge the tenth stops.
  EXPECT_EQ(ticks_down, 10);
  EXPECT_EQ(o.direction, -1);
  EXPECT_EQ(o.step_hz, 0.0);
  EXPECT_DOUBLE_EQ(d.drive(t += kTickS, -1.0).step_hz, 200.0);
}

TEST(StepDir, NeverStepsWhileDirChangesAndNeverJumpsAboveThePullInBand) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> duty(-1.2, 1.2);
  StepDir d(kConfig);
  StepDirOutputs last = d.drive(0.0, 0.0);
  for (int i = 1; i < 20'000; ++i) {
    const StepDirOutputs o = d.drive(i * kTickS, i % 7 == 0 ? 0.0 : duty(random));
    if (o.direction != last.direction) {
      ASSERT_EQ(last.step_hz, 0.0) << "DIR turned while stepping, tick " << i;
      ASSERT_EQ(o.step_hz, 0.0) << "a step in DIR's set-up tick " << i;
    }
    const double change = std::fabs(o.step_hz - last.step_hz);
    const bool in_band = std::min(o.step_hz, last.step_hz) <= kConfig.start_hz;
    const double allowed = kConfig.accel_hz_s * kTickS + (in_band ? kConfig.start_hz : 0.0);
    ASSERT_LE(change, allowed + 1e-9) << "tick " << i;
    ASSERT_LE(o.step_hz, kConfig.max_step_hz);
    last = o;
  }
}

TEST(StepDir, ABadNumberOrADisableStopsAndDisablesTheDriver) {
  StepDir d(kConfig);
  for (int i = 0; i < 20; ++i) (void)d.drive(i * kTickS, 1.0);
  const StepDirOutputs bad = d.drive(1.0, std::nan(""));
  EXPECT_EQ(bad.step_hz, 0.0);
  EXPECT_FALSE(bad.enable);
  // Driven again: from a standstill, at the pull-in rate, not where it was.
  EXPECT_DOUBLE_EQ(d.drive(1.05, 1.0).step_hz, 200.0);
  EXPECT_FALSE(d.disable(1.1).enable);
  EXPECT_DOUBLE_EQ(d.drive(1.15, 1.0).step_hz, 200.0);
}

TEST(StepDirConfig, RefusesWhatNoStepperCanDo) {
  EXPECT_TRUE(StepDirConfig::make(2000.0, 200.0, 4000.0));
  EXPECT_TRUE(StepDirConfig::make(2000.0, 0.0, 4000.0));
  EXPECT_FALSE(StepDirConfig::make(0.0, 0.0, 4000.0));
  EXPECT_FALSE(StepDirConfig::make(2000.0, 2500.0, 4000.0));
  EXPECT_FALSE(StepDirConfig::make(2000.0, -1.0, 4000.0));
  EXPECT_FALSE(StepDirConfig::make(2000.0, 200.0, 0.0));
  EXPECT_FALSE(StepDirConfig::make(std::nan(""), 200.0, 4000.0));
}

}  // namespace
}  // namespace azt::control
