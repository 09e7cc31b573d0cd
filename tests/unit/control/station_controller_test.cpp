#include "azt/control/station_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/sim/axis_plant.hpp"
#include "azt/sim/reference_station.hpp"

namespace azt::control {
namespace {

/// The reference station's control settings around a noiseless plant pair, read perfectly
/// every tick: enough to see what the station controller asks of the motors.
struct Rig {
  sim::StationSimSetup setup = sim::reference_station(16, 0.1);
  StationControlConfig config() const {
    StationControlConfig c;
    c.az_control = setup.station.az_control;
    c.el_control = setup.station.el_control;
    c.az_control.lsb_deg = 360.0 / 65536;
    c.el_control.lsb_deg = 360.0 / 65536;
    c.az_supervisor = setup.station.az_supervisor;
    c.el_supervisor = setup.station.el_supervisor;
    c.az_range = setup.station.az_range;
    c.el_range = setup.station.el_range;
    c.tick_s = setup.station.tick_s;
    return c;
  }
  sim::AxisPlant az{setup.plant.az};
  sim::AxisPlant el{setup.plant.el};
  StationController station{config(), AzEl{setup.plant.az.start_deg, setup.plant.el.start_deg}};
  double t = 0.0;

  void run(const Demand& demand, double seconds) {
    for (double end = t + seconds; t < end; t += setup.station.tick_s) {
      station.on_encoder_reading(t, wrap_360(az.shaft_deg()), el.shaft_deg());
      const Duties d = station.tick(t, demand, AzEl{});
      az.step(d.az, setup.station.tick_s);
      el.step(d.el, setup.station.tick_s);
    }
  }
};

TEST(StationController, DrivesBothAxesToAPositionDemand) {
  Rig rig;
  Demand go;
  go.position = AzEl{rig.setup.plant.az.start_deg + 20.0, 30.0};
  rig.run(go, 120.0);
  const auto sky = rig.station.sky_position(rig.t);
  ASSERT_TRUE(sky.has_value());
  EXPECT_NEAR(sky->az_deg, wrap_360(rig.setup.plant.az.start_deg + 20.0), 0.12);
  EXPECT_NEAR(sky->el_deg, 30.0, 0.12);
  EXPECT_FALSE(rig.station.faulted());
}

// Found by bench/rotctld_compare.sh (rotctld clients hammering P with targets 10–20° apart): the
// supervisor compared the distance to a goal that kept jumping away and latched "runaway".
TEST(StationController, TargetsJumpingAroundNeverLookLikeAFault) {
  Rig rig;
  Demand go;
  for (int i = 0; i < 200; ++i) {
    // a new target every 0.1 s, alternately further ahead and behind on both axes
    const double step = (i % 2 == 0 ? 1.0 : -1.0) * (5.0 + (i % 7));
    go.position = AzEl{wrap_360(rig.setup.plant.az.start_deg + 10.0 + step), 30.0 + step};
    rig.run(go, 0.1);
    ASSERT_FALSE(rig.station.faulted()) << "after target " << i;
  }
}

// The seed's UP button: +0.50° of elevation correction makes the antenna point 0.50° higher while
// the read-back position stays on the target; an offset change of several degrees is a
// calibration, not an encoder jump, and moves the shaft by it without a fault.
TEST(StationController, CorrectionsChangedAtRuntimeMoveTheAntennaByTheChange) {
  Rig rig;
  Demand go;
  go.position = AzEl{wrap_360(rig.setup.plant.az.start_deg + 10.0), 30.0};
  rig.run(go, 60.0);
  const double el_before = rig.el.shaft_deg();
  PositionCorrections c;
  ASSERT_TRUE(c.user.nudge_el(50));
  rig.station.set_corrections(c);
  rig.run(go, 30.0);
  EXPECT_NEAR(rig.el.shaft_deg() - el_before, 0.50, 0.12);
  ASSERT_TRUE(rig.station.sky_position(rig.t).has_value());
  EXPECT_NEAR(rig.station.sky_position(rig.t)->el_deg, 30.0, 0.12);
  c.offsets = *AxisOffsets::make(0.0, 3.4);  // the encoder reads 3.4° low
  rig.station.set_corrections(c);
  rig.run(go, 30.0);
  EXPECT_FALSE(rig.station.faulted()) << rig.station.el().reason;
  EXPECT_NEAR(rig.el.shaft_deg() - el_before, 0.50 - 3.4, 0.12);
}

TEST(StationController, AJogRunsTowardsTheTravelEndAndHoldingStopsIt) {
  Rig rig;
  Demand jog;
  jog.jog = Jog{0, 1};
  const double el0 = rig.el.shaft_deg();
  rig.run(jog, 5.0);
  const double moved = rig.el.shaft_deg() - el0;
  EXPECT_GT(moved, 1.0);
  rig.run(Demand{}, 5.0);  // hold
  const double held = rig.el.shaft_deg();
  rig.run(Demand{}, 5.0);
  EXPECT_NEAR(rig.el.shaft_deg(), held, 0.01);
  EXPECT_DOUBLE_EQ(rig.station.el().duty, 0.0);
}

// A game pad's stick half way: the axis runs at the asked fraction of its full rate (a moving
// goal with its rate fed forward), not flat out; full speed still runs flat out.
TEST(StationController, AContinuousMoveBelowFullSpeedRunsAtThatFractionOfTheFullRate) {
  const auto rate_over = [](double speed) {
    Rig rig;
    Demand jog;
    jog.jog = Jog{1, 0, speed, 1.0};
    rig.run(jog, 5.0);  // past the soft start
    const double from = rig.az.shaft_deg();
    rig.run(jog, 10.0);
    return (rig.az.shaft_deg() - from) / 10.0;
  };
  const double full = Rig{}.config().az_control.max_rate_deg_s;
  EXPECT_NEAR(rate_over(0.4), 0.4 * full, 0.03 * full);
  EXPECT_NEAR(rate_over(0.1), 0.1 * full, 0.03 * full);
  EXPECT_GT(rate_over(1.0), 0.95 * full);
}

TEST(StationController, AStoppedSlowMoveDoesNotCarryOnFromItsOldGoal) {
  Rig rig;
  Demand jog;
  jog.jog = Jog{0, 1, 1.0, 0.5};
  rig.run(jog, 4.0);
  rig.run(Demand{}, 5.0);  // hold
  const double held = rig.el.shaft_deg();
  jog.jog = Jog{0, -1, 1.0, 0.5};  // the other way: from where it stands, not from the old goal
  rig.run(jog, 2.0);
  EXPECT_LT(rig.el.shaft_deg(), held);
  EXPECT_FALSE(rig.station.faulted()) << rig.station.el().reason;
}

TEST(StationController, NoReadingsMeansNoPositionAndNoMotion) {
  Rig rig;
  Demand go;
  go.position = AzEl{10.0, 10.0};
  const Duties d = rig.station.tick(1.0, go, AzEl{});
  EXPECT_DOUBLE_EQ(d.az, 0.0);
  EXPECT_DOUBLE_EQ(d.el, 0.0);
  EXPECT_FALSE(rig.station.sky_position(1.0).has_value());
}

TEST(StationController, EmergencyStopZeroesBothDutiesAndLatches) {
  Rig rig;
  Demand go;
  go.position = AzEl{rig.setup.plant.az.start_deg + 90.0, 60.0};
  rig.run(go, 2.0);
  EXPECT_NE(rig.station.az().duty, 0.0);
  rig.station.emergency_stop(rig.t);
  EXPECT_DOUBLE_EQ(rig.station.az().duty, 0.0);
  EXPECT_TRUE(rig.station.faulted());
  rig.run(go, 1.0);
  EXPECT_DOUBLE_EQ(rig.station.az().duty, 0.0);
  rig.station.clear_faults();
  rig.run(go, 1.0);
  EXPECT_NE(rig.station.az().duty, 0.0);
}

TEST(StationController, ATrippedLimitStopsTheDriveTowardsItAtOnceAndAllowsTheWayBack) {
  Rig rig;
  Demand cw;
  cw.position = AzEl{rig.setup.plant.az.start_deg + 90.0, rig.setup.plant.el.start_deg};
  rig.run(cw, 3.0);
  ASSERT_GT(rig.station.az().duty, 0.0);
  // The clockwise switch opens between ticks: the duty is zero in the answer, not at the next tick.
  LimitSwitches limits;
  limits.az_cw = true;
  const Duties now = rig.station.set_limits(limits);
  EXPECT_DOUBLE_EQ(now.az, 0.0);
  // A limit on the other side or on the other axis leaves this one alone.
  rig.run(cw, 5.0);
  EXPECT_DOUBLE_EQ(rig.station.az().duty, 0.0);
  EXPECT_FALSE(rig.station.faulted()) << "held at a switch is not a stall";
  const double held_at = rig.az.shaft_deg();
  Demand ccw;
  ccw.position = AzEl{held_at - 30.0, rig.setup.plant.el.start_deg};
  rig.run(ccw, 3.0);
  EXPECT_LT(rig.station.az().duty, 0.0) << "moving away from a tripped switch is allowed";
  EXPECT_LT(rig.az.shaft_deg(), held_at);
}

TEST(StationController, ElevationLimitsBlockOnlyTheirOwnDirection) {
  Rig rig;
  LimitSwitches limits;
  limits.el_down = true;
  rig.station.set_limits(limits);
  Demand down;
  down.position = AzEl{rig.setup.plant.az.start_deg, rig.setup.plant.el.start_deg - 5.0};
  rig.run(down, 3.0);
  EXPECT_DOUBLE_EQ(rig.station.el().duty, 0.0);
  Demand up;
  up.position = AzEl{rig.setup.plant.az.start_deg, rig.setup.plant.el.start_deg + 20.0};
  rig.run(up, 3.0);
  EXPECT_GT(rig.station.el().duty, 0.0);
  limits.el_up = true;
  EXPECT_DOUBLE_EQ(rig.station.set_limits(limits).el, 0.0);
}

// The same station with relays on azimuth and a rotator box (setpoint) on elevation.
struct MixedRig {
  sim::StationSimSetup setup = sim::reference_station(16, 0.1);
  static constexpr double kBoxBandDeg = 0.5;  ///< the box's own deadband in the model below
  StationControlConfig config() const {
    Rig plain;
    StationControlConfig c = plain.config();
    c.az_drive.kind = DriveKind::Relay;
    c.az_drive.relay.window_deg = 1.0;
    c.az_drive.relay.lsb_deg = c.az_control.lsb_deg;
    c.el_drive.kind = DriveKind::Setpoint;
    c.el_drive.setpoint_band_deg = 2.0;
    return c;
  }
  sim::AxisPlant az{setup.plant.az};
  sim::AxisPlant el{setup.plant.el};
  StationController station{config(), AzEl{setup.plant.az.start_deg, setup.plant.el.start_deg}};
  double t = 0.0;
  std::optional<double> box_setpoint;
  double last_az_duty = 0.0;
  int direct_reversals = 0;  ///< Forward straight to Reverse (or back) between two ticks

  void run(const Demand& demand, double seconds) {
    for (double end = t + seconds; t < end; t += setup.station.tick_s) {
      station.on_encoder_reading(t, wrap_360(az.shaft_deg()), el.shaft_deg());
      const Duties d = station.tick(t, demand, AzEl{});
      if (d.az * last_az_duty < 0.0) ++direct_reversals;
      last_az_duty = d.az;
      if (d.el_setpoint_deg) box_setpoint = d.el_setpoint_deg;
      // The rotator box: full speed towards its setpoint beyond its deadband.
      const double box_error = box_setpoint ? *box_setpoint - el.shaft_deg() : 0.0;
      const double box_duty =
          std::fabs(box_error) > kBoxBandDeg ? std::copysign(1.0, box_error) : 0.0;
      az.step(d.az, setup.station.tick_s);
      el.step(box_duty, setup.station.tick_s);
    }
  }
};

TEST(StationController, RelayAndSetpointAxesReachTheDemand) {
  MixedRig rig;
  Demand go;
  go.position = AzEl{rig.setup.plant.az.start_deg + 30.0, 40.0};
  rig.run(go, 120.0);
  const auto sky = rig.station.sky_position(rig.t);
  ASSERT_TRUE(sky.has_value());
  // Relays stop within the window (1°) plus a step; the box within its own deadband plus coast.
  EXPECT_NEAR(sky->az_deg, wrap_360(rig.setup.plant.az.start_deg + 30.0), 1.1);
  EXPECT_NEAR(sky->el_deg, 40.0, 1.0);
  ASSERT_TRUE(rig.box_setpoint.has_value());
  EXPECT_DOUBLE_EQ(*rig.box_setpoint, 40.0) << "the setpoint is the planned target itself";
  EXPECT_EQ(rig.direct_reversals, 0);
  EXPECT_GE(rig.station.starts_az(), 1U);
  EXPECT_FALSE(rig.station.faulted());
  const Duties d = rig.station.tick(rig.t, go, AzEl{});
  EXPECT_TRUE(d.el_setpoint_deg.has_value());
  EXPECT_FALSE(d.az_setpoint_deg.has_value());
}

TEST(StationController, SetpointAxisIsSentWhereItStandsOnAnEStopOrALimit) {
  MixedRig rig;
  Demand up;
  up.position = AzEl{rig.setup.plant.az.start_deg, 60.0};
  rig.run(up, 3.0);
  ASSERT_TRUE(rig.box_setpoint.has_value());
  EXPECT_DOUBLE_EQ(*rig.box_setpoint, 60.0);
  LimitSwitches limits;
  limits.el_up = true;
  const Duties now = rig.station.set_limits(limits);
  ASSERT_TRUE(now.el_setpoint_deg.has_value());
  EXPECT_DOUBLE_EQ(*now.el_setpoint_deg, rig.station.el().mount_deg);
  rig.run(up, 1.0);
  EXPECT_LT(*rig.box_setpoint, 60.0) << "a setpoint beyond a tripped switch was sent";
  rig.station.set_limits(LimitSwitches{});
  rig.run(up, 1.0);
  EXPECT_DOUBLE_EQ(*rig.box_setpoint, 60.0);
  rig.station.emergency_stop(rig.t);
  const Duties stopped = rig.station.tick(rig.t, up, AzEl{});
  ASSERT_TRUE(stopped.el_setpoint_deg.has_value());
  EXPECT_DOUBLE_EQ(*stopped.el_setpoint_deg, rig.station.el().mount_deg);
}

// A STOP (no target) mid-move stops a rotator box where it stands, as it stops a motor; the
// setpoint is not re-sent at every tick of the hold (that would chase the coast).
TEST(StationController, StopMidMoveSendsTheSetpointAxisWhereItStands) {
  MixedRig rig;
  Demand up;
  up.position = AzEl{rig.setup.plant.az.start_deg, 60.0};
  rig.run(up, 3.0);
  ASSERT_TRUE(rig.box_setpoint.has_value());
  ASSERT_DOUBLE_EQ(*rig.box_setpoint, 60.0);
  rig.run(Demand{}, 0.05);  // one tick of STOP, on the reading of that tick
  EXPECT_LT(*rig.box_setpoint, 50.0) << "STOP left the box driving to its old setpoint";
  EXPECT_DOUBLE_EQ(*rig.box_setpoint, rig.station.el().mount_deg);
  const double held = *rig.box_setpoint;
  rig.run(Demand{}, 2.0);
  EXPECT_DOUBLE_EQ(*rig.box_setpoint, held) << "the held setpoint followed the coast";
  EXPECT_FALSE(rig.station.faulted());
}

TEST(StationController, RelayAxisStopsAtATrippedLimitAndOnEStop) {
  MixedRig rig;
  Demand cw;
  cw.position = AzEl{rig.setup.plant.az.start_deg + 60.0, rig.setup.plant.el.start_deg};
  rig.run(cw, 2.0);
  ASSERT_EQ(rig.station.az().duty, 1.0);
  LimitSwitches limits;
  limits.az_cw = true;
  EXPECT_DOUBLE_EQ(rig.station.set_limits(limits).az, 0.0);
  rig.run(cw, 2.0);
  EXPECT_DOUBLE_EQ(rig.station.az().duty, 0.0);
  EXPECT_FALSE(rig.station.faulted());
  rig.station.set_limits(LimitSwitches{});
  rig.run(cw, 2.0);
  EXPECT_DOUBLE_EQ(rig.station.az().duty, 1.0);
  rig.station.emergency_stop(rig.t);
  EXPECT_DOUBLE_EQ(rig.station.az().duty, 0.0);
}

TEST(StationController, AnAbsoluteAzimuthSensorKeepsItsTurn) {
  Rig rig;
  StationControlConfig c = rig.config();
  c.az_range = AzimuthRange{0.0, 450.0};
  c.az_absolute = true;
  StationController station(c, AzEl{180.0, 10.0});  // believed at 180°, really at 400°
  station.on_encoder_reading(0.0, 400.0, 10.0);
  EXPECT_DOUBLE_EQ(station.az().mount_deg, 400.0);
  c.az_absolute = false;
  StationController single_turn(c, AzEl{180.0, 10.0});
  single_turn.on_encoder_reading(0.0, 400.0, 10.0);
  EXPECT_DOUBLE_EQ(single_turn.az().mount_deg, 40.0)
      << "a single-turn reading goes to the near side";
}

// Found by the pass simulation: a shaft that coasts a hair past the 450° stop read as 90°, a
// latched encoder-jump fault.
TEST(StationController, AReadingJustPastTheOverlapStopStaysOnItsSide) {
  Rig rig;
  StationControlConfig c = rig.config();
  c.az_range = AzimuthRange{0.0, 450.0};
  StationController station(c, AzEl{449.99, 10.0});
  station.on_encoder_reading(0.0, 89.99, 10.0);
  station.on_encoder_reading(0.05, 90.001, 10.0);  // 450.001 on the mount
  EXPECT_NEAR(station.az().mount_deg, 450.001, 1e-9);
  EXPECT_FALSE(station.faulted());
}

// The direction test (docs/hardware.md): one axis open loop and slow, the other holding.
Demand direction_test(bool azimuth) {
  Demand d;
  d.test = AxisTest{azimuth, 1};
  return d;
}

TEST(StationController, TheDirectionTestDrivesOneAxisSlowlyTheOneWay) {
  Rig rig;
  rig.run(Demand{}, 1.0);
  const double az0 = rig.az.shaft_deg();
  const double el0 = rig.el.shaft_deg();
  rig.run(direction_test(false), 1.0);
  EXPECT_GT(rig.el.shaft_deg() - el0, 0.1);
  EXPECT_NEAR(rig.az.shaft_deg(), az0, 1e-9);
  EXPECT_GT(rig.station.el().duty, 0.0);
  EXPECT_LT(rig.station.el().duty, rig.setup.station.el_supervisor.driven_duty);
  EXPECT_FALSE(rig.station.faulted());
}

TEST(StationController, AReversedMotorUnderTheDirectionTestIsAnAnswerNotARunaway) {
  Rig rig;
  const double az0 = rig.az.shaft_deg();
  for (double end = rig.t + 1.0; rig.t < end; rig.t += rig.setup.station.tick_s) {
    rig.station.on_encoder_reading(rig.t, wrap_360(rig.az.shaft_deg()), rig.el.shaft_deg());
    const Duties d = rig.station.tick(rig.t, direction_test(true), AzEl{});
    rig.az.step(-d.az, rig.setup.station.tick_s);  // the motor's wires swapped
    rig.el.step(d.el, rig.setup.station.tick_s);
  }
  EXPECT_LT(rig.az.shaft_deg() - az0, -0.1);
  EXPECT_FALSE(rig.station.faulted());
  // The test over, the holding axis ramps down (a soft stop) and stays put.
  rig.run(Demand{}, 1.0);
  EXPECT_EQ(rig.station.az().duty, 0.0);
}

TEST(StationController, TheDirectionTestStopsAtATrippedSwitch) {
  Rig rig;
  LimitSwitches limits;
  limits.el_up = true;
  rig.station.set_limits(limits);
  const double el0 = rig.el.shaft_deg();
  rig.run(direction_test(false), 1.0);
  EXPECT_EQ(rig.station.el().duty, 0.0);
  EXPECT_NEAR(rig.el.shaft_deg(), el0, 1e-9);
}

}  // namespace
}  // namespace azt::control
