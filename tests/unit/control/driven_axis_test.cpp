#include "azt/control/driven_axis.hpp"

#include <gtest/gtest.h>

namespace azt::control {
namespace {

constexpr double kTickS = 0.05;

DrivenAxis make_axis(DriveKind kind, double start_deg = 0.0) {
  AxisControlConfig control;
  control.lsb_deg = 360.0 / 4096;
  AxisDriveConfig drive;
  drive.kind = kind;
  return DrivenAxis(control, SupervisorConfig{}, drive, start_deg, kTickS);
}

TEST(DrivenAxis, APwmAxisDrivesTowardsItsTargetAndHoldsWithoutOne) {
  DrivenAxis axis = make_axis(DriveKind::Pwm);
  axis.on_reading(0.0, 0.0);
  EXPECT_GT(axis.drive(0.0, 20.0, 0.0), 0.0);
  EXPECT_TRUE(axis.moving());
  EXPECT_EQ(axis.starts(), 1U);
  EXPECT_FALSE(axis.setpoint_deg().has_value());  // duty-driven: no angle to send
  DrivenAxis still = make_axis(DriveKind::Pwm);
  still.on_reading(0.0, 0.0);
  EXPECT_EQ(still.drive(0.0, std::nullopt, 0.0), 0.0);
}

TEST(DrivenAxis, ATrippedSwitchStopsTheDriveIntoItButNotAwayFromIt) {
  DrivenAxis axis = make_axis(DriveKind::Relay);
  double t = 0.0;
  double duty = 0.0;
  for (; t < 3.0 && duty == 0.0; t += kTickS) {  // through the relay's dead time at start
    axis.on_reading(t, 0.0);
    duty = axis.drive(t, 20.0, 0.0);
  }
  ASSERT_EQ(duty, 1.0);
  axis.set_limits(LimitPair{false, true});
  EXPECT_EQ(axis.duty(), 0.0);  // at once, between ticks
  axis.on_reading(t, 0.0);
  EXPECT_EQ(axis.drive(t, 20.0, 0.0), 0.0);
  // Away from the tripped end it may move (after the relay's reversal dead time).
  duty = 0.0;
  for (t += kTickS; t < 6.0 && duty == 0.0; t += kTickS) {
    axis.on_reading(t, 0.0);
    duty = axis.drive(t, -20.0, 0.0);
  }
  EXPECT_EQ(duty, -1.0);
}

TEST(DrivenAxis, TheEmergencyStopHaltsAndLatchesUntilCleared) {
  DrivenAxis axis = make_axis(DriveKind::Setpoint, 5.0);
  axis.on_reading(0.0, 5.0);
  EXPECT_EQ(axis.drive(0.0, 30.0, 0.0), 1.0);
  EXPECT_EQ(axis.setpoint_deg(), 30.0);
  axis.emergency_stop(0.02, "test stop");
  EXPECT_EQ(axis.duty(), 0.0);
  EXPECT_EQ(axis.setpoint_deg(), 5.0);  // sent where it stands
  EXPECT_TRUE(axis.faulted());
  EXPECT_EQ(axis.status().reason, "test stop");
  axis.on_reading(0.05, 5.0);
  EXPECT_EQ(axis.drive(0.05, 30.0, 0.0), 0.0);
  axis.clear_faults();
  axis.on_reading(0.1, 5.0);
  EXPECT_EQ(axis.drive(0.1, 30.0, 0.0), 1.0);
}

TEST(DrivenAxis, ARebaseMovesTheReadingWithoutLookingLikeAJump) {
  DrivenAxis axis = make_axis(DriveKind::Pwm, 10.0);
  axis.on_reading(0.0, 10.0);
  axis.rebase(3.0);
  EXPECT_DOUBLE_EQ(axis.mount_deg(), 13.0);
  axis.on_reading(0.05, 13.0);
  EXPECT_FALSE(axis.faulted());
  EXPECT_DOUBLE_EQ(axis.status().mount_deg, 13.0);
}

}  // namespace
}  // namespace azt::control
