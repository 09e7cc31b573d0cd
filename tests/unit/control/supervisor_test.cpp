// The axis supervisor in virtual time: each fault injected, motion forbidden in the tick that
// detects it, latching and clearing.
#include "azt/control/supervisor.hpp"

#include <gtest/gtest.h>

namespace azt::control {
namespace {

constexpr double kTick = 0.05;

SupervisorConfig config() {
  SupervisorConfig c;
  c.max_rate_deg_s = 1.5;
  return c;
}

TEST(Supervisor, NoReadingNoMotion) {
  AxisSupervisor s(config());
  EXPECT_FALSE(s.check(0.0, 0.0).allow_motion);
  EXPECT_TRUE(s.stale(0.0));
}

TEST(Supervisor, StaleReadingsStopTheMotorsUntilReadingsReturn) {
  AxisSupervisor s(config());
  ASSERT_TRUE(s.on_reading(0.0, 10.0));
  EXPECT_TRUE(s.check(0.1, 0.3).allow_motion);
  EXPECT_TRUE(s.check(0.2, 0.3).allow_motion);    // exactly 200 ms: still fresh
  EXPECT_FALSE(s.check(0.21, 0.3).allow_motion);  // > 200 ms without a valid reading
  EXPECT_EQ(s.fault(), FaultKind::None);          // not latched
  ASSERT_TRUE(s.on_reading(0.25, 10.1));
  EXPECT_TRUE(s.check(0.25, 0.3).allow_motion);
}

TEST(Supervisor, StallLatchesAfterTwoSecondsDrivenWithoutMoving) {
  AxisSupervisor s(config());
  double t = 0.0;
  bool stopped_at_detection = false;
  for (; t < 3.0; t += kTick) {
    ASSERT_TRUE(s.on_reading(t, 10.0 + 0.01 * t));  // frozen shaft: 0.02° in 2 s
    const auto v = s.check(t, 0.8);
    if (s.fault() == FaultKind::Stall) {
      stopped_at_detection = !v.allow_motion;
      break;
    }
  }
  EXPECT_EQ(s.fault(), FaultKind::Stall);
  EXPECT_TRUE(stopped_at_detection);
  EXPECT_NEAR(t, 2.0, kTick + 1e-9);
  EXPECT_NE(s.reason().find("moved less than"), std::string::npos);
  EXPECT_FALSE(s.check(t + kTick, 0.0).allow_motion);  // latched
  s.clear();
  ASSERT_TRUE(s.on_reading(t + 2 * kTick, 10.0));
  EXPECT_TRUE(s.check(t + 2 * kTick, 0.0).allow_motion);
}

TEST(Supervisor, SlowDutyIsNotAStall) {
  AxisSupervisor s(config());
  for (double t = 0.0; t < 10.0; t += kTick) {
    ASSERT_TRUE(s.on_reading(t, 10.0));
    EXPECT_TRUE(s.check(t, 0.2).allow_motion);  // creeping on the final approach
  }
  EXPECT_EQ(s.fault(), FaultKind::None);
}

TEST(Supervisor, MovingAxisIsNotAStall) {
  AxisSupervisor s(config());
  for (double t = 0.0; t < 10.0; t += kTick) {
    ASSERT_TRUE(s.on_reading(t, 10.0 + 0.75 * t));
    EXPECT_TRUE(s.check(t, 0.55).allow_motion);
  }
  EXPECT_EQ(s.fault(), FaultKind::None);
}

TEST(Supervisor, RunawayWhenTheErrorGrowsWhileDriven) {
  AxisSupervisor s(config());
  double t = 0.0;
  for (; t < 3.0 && s.fault() == FaultKind::None; t += kTick) {
    const double position = 10.0 - 1.0 * t;  // reversed motor: moves away at 1°/s
    ASSERT_TRUE(s.on_reading(t, position));
    s.check(t, 0.9);
  }
  EXPECT_EQ(s.fault(), FaultKind::Runaway);
  EXPECT_LT(t, 1.0);  // 0.5° of growth at 1°/s
}

TEST(Supervisor, RunawayWhenTheAxisTurnsBackWhileDriven) {
  AxisSupervisor s(config());
  double t = 0.0;
  for (; t < 4.0 && s.fault() == FaultKind::None; t += kTick) {
    // right way for 1 s, then the gear slips and it runs back at 1°/s under the same drive
    const double position = t < 1.0 ? 10.0 + t : 11.0 - (t - 1.0);
    ASSERT_TRUE(s.on_reading(t, position));
    s.check(t, 0.9);
  }
  EXPECT_EQ(s.fault(), FaultKind::Runaway);
  EXPECT_LE(t, 1.0 + 0.5 + 2 * kTick + 1e-9);  // 0.5° back at 1°/s; t is one tick past it
}

TEST(Supervisor, ImplausibleJumpsAreRejectedThenBecomeAFault) {
  AxisSupervisor s(config());
  ASSERT_TRUE(s.on_reading(0.0, 10.0));
  EXPECT_FALSE(s.on_reading(0.05, 40.0));  // 30° in 50 ms
  const auto v = s.check(0.05, 0.0);
  ASSERT_TRUE(v.position_deg.has_value());
  EXPECT_DOUBLE_EQ(*v.position_deg, 10.0);  // the last good reading stays in use
  EXPECT_TRUE(s.on_reading(0.1, 10.01));    // a single glitch is forgotten
  for (double t = 0.15; t < 1.0; t += kTick) s.on_reading(t, 40.0);
  EXPECT_EQ(s.fault(), FaultKind::EncoderJump);
  EXPECT_FALSE(s.check(1.0, 0.0).allow_motion);
}

TEST(Supervisor, OneCountOfACoarseEncoderIsNotAJump) {
  SupervisorConfig c = config();
  c.lsb_deg = 360.0 / 512.0;  // 9 bits: 0.70° per count, more than max rate × tick + 0.2°
  AxisSupervisor s(c);
  ASSERT_TRUE(s.on_reading(0.0, 10.0));
  EXPECT_TRUE(s.on_reading(0.05, 10.0 + c.lsb_deg));
  AxisSupervisor fine(config());  // without the step size the same change is implausible
  ASSERT_TRUE(fine.on_reading(0.0, 10.0));
  EXPECT_FALSE(fine.on_reading(0.05, 10.0 + c.lsb_deg));
}

TEST(Supervisor, EmergencyStopLatches) {
  AxisSupervisor s(config());
  ASSERT_TRUE(s.on_reading(0.0, 10.0));
  s.emergency_stop(0.0);
  EXPECT_FALSE(s.check(0.0, 0.5).allow_motion);
  EXPECT_EQ(s.fault(), FaultKind::EStop);
  EXPECT_EQ(to_string(s.fault()), "estop");
}

TEST(SupervisorConfig, Validates) {
  SupervisorConfig c;
  c.stale_s = 0;
  EXPECT_FALSE(SupervisorConfig::make(c).ok());
  EXPECT_TRUE(SupervisorConfig::make(SupervisorConfig{}).ok());
}

}  // namespace
}  // namespace azt::control
