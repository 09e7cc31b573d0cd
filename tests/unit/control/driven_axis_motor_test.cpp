// DrivenAxis with a brake and motor protection (brake.hpp, motor_trips.hpp plugged in).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "azt/control/driven_axis.hpp"

namespace azt::control {
namespace {

constexpr double kTickS = 0.05;

BrakeConfig slow_brake(double release_s) {
  BrakeConfig b;
  b.release_s = release_s;
  b.engage_s = 0.3;
  b.idle_s = 1.0;
  return b;
}

MotorTripsConfig trips() {
  MotorTripsConfig t;
  t.axis = "az";
  t.current_limit_a = 5.0;
  t.current_trip_s = 0.5;
  t.temperature_limit_c = 75.0;
  t.temperature_hysteresis_c = 5.0;
  return t;
}

DrivenAxis make_axis(DriveKind kind, std::optional<BrakeConfig> brake,
                     std::optional<MotorTripsConfig> protection = std::nullopt) {
  AxisControlConfig control;
  control.lsb_deg = 360.0 / 4096;
  AxisDriveConfig drive;
  drive.kind = kind;
  drive.relay.lsb_deg = control.lsb_deg;
  drive.brake = brake;
  drive.trips = std::move(protection);
  return DrivenAxis(control, SupervisorConfig{}, drive, 0.0, kTickS);
}

/// A shaft that turns at `rate_deg_s` per unit of duty unless its brake holds it.
struct Shaft {
  double deg = 0.0;
  void step(const DrivenAxis& axis, double duty) {
    const auto s = axis.status();
    if (!s.brake || *s.brake == BrakeState::Released) deg += duty * 1.5 * kTickS;
  }
};

TEST(DrivenAxisBrake, ASlowBrakeDelaysMotionWithoutAStallAndTheSoftStartBeginsFromZero) {
  for (const DriveKind kind : {DriveKind::Pwm, DriveKind::Relay}) {
    DrivenAxis axis = make_axis(kind, slow_brake(3.0));  // longer than the stall window (2 s)
    Shaft shaft;
    std::optional<double> released_from_s;  // the brake's line first on (a relay waits its
                                            // reversal dead time before it wants to start)
    double first_duty_s = -1.0;
    double first_duty = 0.0;
    for (int i = 0; i < 120 && first_duty_s < 0.0; ++i) {
      const double t = i * kTickS;
      axis.on_reading(t, shaft.deg);
      const double duty = axis.drive(t, 20.0, 0.0);
      shaft.step(axis, duty);
      if (axis.status().brake_release && !released_from_s) released_from_s = t;
      if (duty != 0.0) {
        first_duty_s = t;
        first_duty = duty;
      }
    }
    ASSERT_TRUE(released_from_s.has_value()) << to_string(kind);
    EXPECT_LE(*released_from_s, 0.5 + 1e-9) << to_string(kind);  // relays: reversal_dead_s
    EXPECT_GE(first_duty_s, *released_from_s + 3.0 - 1e-9) << to_string(kind);
    EXPECT_LT(first_duty_s, *released_from_s + 3.0 + kTickS + 1e-9) << to_string(kind);
    EXPECT_FALSE(axis.faulted()) << axis.status().reason;
    EXPECT_EQ(axis.starts(), 1U) << to_string(kind);  // the ticks against the brake were none
    switch (kind) {
      case DriveKind::Pwm:  // ramp_s = 1 s: one tick's step from zero
        EXPECT_LE(first_duty, kTickS / 1.0 + 1e-9);
        break;
      case DriveKind::Relay:
      case DriveKind::Setpoint:
        break;  // one speed, or the box's own
    }
  }
}

TEST(DrivenAxisBrake, TheDutyIsNeverNonZeroWhileTheBrakeHoldsOverARandomRun) {
  std::mt19937 rng(20261130);
  std::uniform_real_distribution<double> where(-90.0, 90.0);
  std::uniform_int_distribution<int> what(0, 9);
  for (const DriveKind kind : {DriveKind::Pwm, DriveKind::Relay, DriveKind::Setpoint}) {
    DrivenAxis axis = make_axis(kind, slow_brake(0.8));
    Shaft shaft;
    std::optional<double> target;
    int moving_ticks = 0;
    for (int i = 0; i < 20000; ++i) {
      const double t = i * kTickS;
      if (i % 37 == 0) {
        const int pick = what(rng);
        if (pick < 5) {
          target = where(rng);
        } else if (pick < 8) {
          target.reset();
        } else if (pick == 8) {
          axis.emergency_stop(t, "test");
          EXPECT_FALSE(axis.status().brake_release);
          axis.clear_faults();
        } else {
          axis.set_limits(LimitPair{shaft.deg<-80.0, shaft.deg> 80.0});
        }
      }
      axis.on_reading(t, shaft.deg);
      const double duty = axis.drive(t, target, 0.0);
      const auto s = axis.status();
      ASSERT_TRUE(s.brake.has_value());
      if (duty != 0.0) {
        ++moving_ticks;
        ASSERT_EQ(*s.brake, BrakeState::Released) << to_string(kind) << " at " << t;
        ASSERT_TRUE(s.brake_release);
      }
      shaft.step(axis, duty);
    }
    EXPECT_GT(moving_ticks, 1000) << to_string(kind);  // it did move, often
  }
}

TEST(DrivenAxisBrake, AStopAppliesTheBrakeOnlyAfterTheIdleTime) {
  DrivenAxis axis = make_axis(DriveKind::Pwm, slow_brake(0.5));
  Shaft shaft;
  int i = 0;
  for (; i < 400 && !(shaft.deg > 5.0); ++i) {
    axis.on_reading(i * kTickS, shaft.deg);
    shaft.step(axis, axis.drive(i * kTickS, 10.0, 0.0));
  }
  ASSERT_GT(shaft.deg, 5.0);
  // STOP: the soft stop winds the duty down, then the brake waits idle_s before it holds.
  std::optional<double> stopped_s;
  std::optional<double> engaged_s;
  for (; i < 800 && !engaged_s; ++i) {
    const double t = i * kTickS;
    axis.on_reading(t, shaft.deg);
    const double duty = axis.drive(t, std::nullopt, 0.0);
    shaft.step(axis, duty);
    if (duty == 0.0 && !stopped_s) stopped_s = t;
    if (!axis.status().brake_release) engaged_s = t;
  }
  ASSERT_TRUE(stopped_s && engaged_s);
  EXPECT_NEAR(*engaged_s - *stopped_s, 1.0, kTickS + 1e-9);
  EXPECT_TRUE(axis.status().brake == BrakeState::Engaging);
}

TEST(DrivenAxisBrake, TheEmergencyStopAppliesTheBrakeAtOnceAndItStaysAppliedWhileLatched) {
  DrivenAxis axis = make_axis(DriveKind::Pwm, slow_brake(0.5));
  Shaft shaft;
  int i = 0;
  for (; i < 40; ++i) {
    axis.on_reading(i * kTickS, shaft.deg);
    shaft.step(axis, axis.drive(i * kTickS, 30.0, 0.0));
  }
  ASSERT_GT(axis.duty(), 0.0);
  axis.emergency_stop(i * kTickS, "e-stop");
  EXPECT_EQ(axis.duty(), 0.0);
  EXPECT_FALSE(axis.status().brake_release);
  // Still wanted to move, but latched: the brake is not released again.
  for (int k = 0; k < 100; ++k, ++i) {
    axis.on_reading(i * kTickS, shaft.deg);
    EXPECT_EQ(axis.drive(i * kTickS, 30.0, 0.0), 0.0);
    EXPECT_FALSE(axis.status().brake_release);
  }
}

TEST(DrivenAxisTrips, AnOverTemperatureTripsLatchesAndIsResetOnlyOnceCooled) {
  DrivenAxis axis = make_axis(DriveKind::Pwm, slow_brake(0.5), trips());
  int i = 0;
  for (; i < 40; ++i) {
    axis.on_reading(i * kTickS, 0.0);
    axis.on_motor_readings(i * kTickS, MotorReadings{1.0, 60.0, false});
    axis.drive(i * kTickS, 30.0, 0.0);
  }
  ASSERT_GT(axis.duty(), 0.0);
  axis.on_motor_readings(i * kTickS, MotorReadings{1.0, 81.0, false});
  EXPECT_EQ(axis.duty(), 0.0);  // at once, before the next drive
  EXPECT_FALSE(axis.status().brake_release);
  EXPECT_TRUE(axis.faulted());
  EXPECT_EQ(axis.status().fault, FaultKind::MotorTrip);
  EXPECT_EQ(axis.status().reason, "az: motor temperature 81.0 °C above 75 °C");
  // Cooled a little: still too warm to reset.
  axis.on_motor_readings(i * kTickS, MotorReadings{0.0, 72.0, false});
  axis.clear_faults();
  EXPECT_TRUE(axis.faulted());
  EXPECT_NE(axis.status().reset_refused.find("not yet below 70 °C"), std::string::npos)
      << axis.status().reset_refused;
  for (int k = 0; k < 20; ++k, ++i) {
    axis.on_reading(i * kTickS, 0.0);
    EXPECT_EQ(axis.drive(i * kTickS, 30.0, 0.0), 0.0);
    EXPECT_FALSE(axis.status().brake_release);
  }
  axis.on_motor_readings(i * kTickS, MotorReadings{0.0, 69.5, false});
  axis.clear_faults();
  EXPECT_FALSE(axis.faulted());
  EXPECT_TRUE(axis.status().reset_refused.empty());
  double duty = 0.0;
  for (int k = 0; k < 40 && duty == 0.0; ++k, ++i) {
    axis.on_reading(i * kTickS, 0.0);
    duty = axis.drive(i * kTickS, 30.0, 0.0);
  }
  EXPECT_GT(duty, 0.0);  // moves again, after the brake's release
}

TEST(DrivenAxisTrips, AnOverCurrentHeldTripsButAShorterStartSurgeDoesNot) {
  DrivenAxis axis = make_axis(DriveKind::Pwm, std::nullopt, trips());
  int i = 0;
  auto run = [&](double amps, int ticks) {
    for (int k = 0; k < ticks; ++k, ++i) {
      axis.on_reading(i * kTickS, 0.0);
      axis.on_motor_readings(i * kTickS, MotorReadings{amps, std::nullopt, std::nullopt});
      axis.drive(i * kTickS, 30.0, 0.0);
    }
  };
  run(12.0, 9);  // 0.4 s: a start surge
  run(2.0, 20);
  EXPECT_FALSE(axis.faulted());
  EXPECT_GT(axis.duty(), 0.0);
  run(12.0, 11);  // 0.5 s held
  EXPECT_TRUE(axis.faulted());
  EXPECT_EQ(axis.duty(), 0.0);
  EXPECT_EQ(axis.status().reason, "az: motor current 12.0 A above 5 A for 0.5 s");
  run(0.0, 1);
  axis.clear_faults();  // the current is gone: the reset is taken
  EXPECT_FALSE(axis.faulted());
}

TEST(DrivenAxisTrips, ADriverFaultTripsAtOnceAndWithoutProtectionReadingsAreIgnored) {
  DrivenAxis axis = make_axis(DriveKind::Relay, std::nullopt, trips());
  axis.on_motor_readings(0.0, MotorReadings{std::nullopt, std::nullopt, true});
  EXPECT_EQ(axis.status().reason, "az: motor driver reports a fault");
  DrivenAxis unwatched = make_axis(DriveKind::Relay, std::nullopt);
  unwatched.on_motor_readings(0.0, MotorReadings{100.0, 150.0, true});
  EXPECT_FALSE(unwatched.faulted());
}

}  // namespace
}  // namespace azt::control
