// A pulse-counted actuator dish driven by DrivenAxis itself (pulse_axis.hpp plugged in): the
// plant's reed pulses and home-switch edges come through a ports::PulseInput, the axis homes at
// start under its supervisor, refuses its target with Homing's words until homed, tracks once
// homed, and a pulse dropped on the way latches a PositionLost fault at the next pass of the home
// switch (the same run without the drop passes clean). The dish is the worked example of
// docs/hardware.md ("Linear actuators"): 1 pulse per millimetre through the triangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "azt/control/driven_axis.hpp"
#include "azt/ports/pulse_input.hpp"
#include "azt/sim/actuator_dish_plant.hpp"
#include "pulse_dish_fixture.hpp"

namespace azt::control {
namespace {

using pulse_dish::dish;
using pulse_dish::kStartDeg;
using pulse_dish::kTickS;
using pulse_dish::PlantPulses;
using pulse_dish::pulse_config;

struct PulsedAxis {
  sim::ActuatorDishPlant plant = sim::ActuatorDishPlant::make(dish()).value();
  PlantPulses input{plant};
  PulseAxis probe = PulseAxis::make(pulse_config()).value();  // for the scale's step only
  DrivenAxis axis = make_axis();

  DrivenAxis make_axis() const {
    AxisControlConfig control;
    control.window_deg = 0.2;
    control.lsb_deg = probe.scale().max_deg_per_count();  // 1 mm at the extended end
    control.max_rate_deg_s = 2.5;
    control.ramp_s = 0.5;
    control.min_duty = 0.1;
    control.time_constant_s = 0.15;
    SupervisorConfig supervisor;
    supervisor.max_rate_deg_s = 3.0;
    supervisor.stale_s = 0.5;
    AxisDriveConfig drive;
    drive.pulses = pulse_config();
    return {AxisControlConfig::make(control).value(), supervisor, drive, kStartDeg, kTickS};
  }

  void tick(std::optional<double> target_deg = std::nullopt, double rate_deg_s = 0.0) {
    const double now_s = plant.now_s();
    const auto edges = input.take_edges();
    axis.on_pulse_edges(now_s, edges);
    const double duty = axis.drive(now_s, target_deg, rate_deg_s);
    input.queue(plant.step(duty, kTickS));
  }

  void home() {
    ASSERT_EQ(axis.home(plant.now_s(), input.home_closed()), std::nullopt);
    while (axis.pulses()->homing_active() && plant.now_s() < 300.0) tick(kStartDeg);
    tick(kStartDeg);  // the reading of the homed count
  }

  void hold(double target_deg, double seconds) {
    const double end_s = plant.now_s() + seconds;
    while (plant.now_s() < end_s) tick(target_deg);
  }
};

TEST(DrivenAxisPulses, RefusesItsTargetWithHomingsWordsUntilHomed) {
  PulsedAxis p;
  p.tick(40.0);
  EXPECT_EQ(p.axis.duty(), 0.0);  // held: no angle to drive to
  EXPECT_EQ(p.axis.status().held, "not homed: homing has not run");
  EXPECT_EQ(p.axis.status().homing, HomingState::NotHomed);
  EXPECT_FALSE(p.axis.faulted());
  ASSERT_EQ(p.axis.home(p.plant.now_s(), p.input.home_closed()), std::nullopt);
  p.tick(40.0);
  EXPECT_LT(p.axis.duty(), 0.0);  // homing's seek (towards the retracted end), not the target
  EXPECT_EQ(p.axis.status().held, "not homed: homing in progress (seeking the home switch)");
}

TEST(DrivenAxisPulses, HomesUnderTheSupervisorThenTracksTheCountedAngle) {
  PulsedAxis p;
  p.home();
  const AxisStatus homed = p.axis.status();
  ASSERT_EQ(homed.homing, HomingState::Homed) << p.axis.pulses()->homing().reason();
  EXPECT_EQ(homed.fault, FaultKind::None) << homed.reason;
  EXPECT_TRUE(homed.held.empty());
  EXPECT_LT(p.plant.now_s(), 60.0);
  // Referenced: the reading is the true angle within one count (0.144° at the retracted end).
  const double step_deg = p.probe.scale().deg_per_count(0);
  EXPECT_NEAR(p.axis.mount_deg(), p.plant.angle_deg(), step_deg);
  // Follows a slow ramp 20° → 30° at 0.02°/s.
  p.hold(20.0, 30.0);
  const double start_s = p.plant.now_s();
  double worst_deg = 0.0;
  while (p.plant.now_s() < start_s + 500.0) {
    const double target = 20.0 + 0.02 * (p.plant.now_s() - start_s);
    p.tick(target, 0.02);
    worst_deg = std::max(worst_deg, std::fabs(p.plant.angle_deg() - target));
  }
  EXPECT_FALSE(p.axis.faulted()) << p.axis.status().reason;
  const double bound_deg =
      p.axis.control_config().start_threshold_deg() + p.probe.scale().deg_per_count(230);
  EXPECT_LE(worst_deg, bound_deg);
  RecordProperty("max_error_deg", std::to_string(worst_deg));
}

/// Homes, goes to 25°, then parks 4 mm past the home switch's make point (521 mm).
void out_and_back(PulsedAxis& p, std::optional<double> drop_pulse_after_s) {
  p.home();
  ASSERT_TRUE(p.axis.pulses()->homed());
  if (drop_pulse_after_s) p.plant.drop_pulse_after(p.plant.now_s() + *drop_pulse_after_s);
  p.hold(25.0, 60.0);
  p.hold(p.plant.geometry().angle_deg(521.0).value(), 80.0);
  EXPECT_TRUE(p.plant.home_closed());
}

TEST(DrivenAxisPulses, PassesTheHomeSwitchCleanWithoutADroppedPulse) {
  PulsedAxis p;
  out_and_back(p, std::nullopt);
  EXPECT_FALSE(p.axis.faulted()) << p.axis.status().reason;
  EXPECT_EQ(p.axis.pulses()->homing().last_pass_difference(), 0);
}

TEST(DrivenAxisPulses, ADroppedPulseLatchesPositionLostUntilHomedAgain) {
  PulsedAxis p;
  out_and_back(p, 5.0);
  EXPECT_EQ(p.plant.pulses_dropped(), 1U);
  const AxisStatus lost = p.axis.status();
  ASSERT_EQ(lost.fault, FaultKind::PositionLost);
  EXPECT_EQ(lost.reason.rfind("position lost: 1 count lost", 0), 0U) << lost.reason;
  EXPECT_EQ(lost.held.rfind("not homed: position lost", 0), 0U) << lost.held;
  p.tick(30.0);
  EXPECT_EQ(p.axis.duty(), 0.0);  // stopped: no target is driven
  // Homing again is the cure: the fault goes and the axis tracks again.
  p.home();
  EXPECT_FALSE(p.axis.faulted()) << p.axis.status().reason;
  EXPECT_TRUE(p.axis.pulses()->homed());
  p.hold(25.0, 60.0);
  EXPECT_NEAR(p.plant.angle_deg(), 25.0, p.axis.control_config().start_threshold_deg());
}

TEST(DrivenAxisPulses, HomingWithoutPulsesFailsWithWordsAndHolds) {
  PulsedAxis p;
  ASSERT_EQ(p.axis.home(p.plant.now_s(), p.input.home_closed()), std::nullopt);
  for (int i = 0; i < 300; ++i) {
    const double now_s = p.plant.now_s();
    (void)p.input.take_edges();  // the sensor's wire is cut: nothing arrives
    p.axis.on_pulse_edges(now_s, {});
    p.plant.step(p.axis.drive(now_s, 30.0, 0.0), kTickS);
  }
  const AxisStatus s = p.axis.status();
  EXPECT_EQ(s.homing, HomingState::Failed);
  EXPECT_EQ(s.held.rfind("not homed: homing failed: seeking the home switch: no pulses", 0), 0U)
      << s.held;
  EXPECT_EQ(p.axis.duty(), 0.0);
}

TEST(PulseAxis, CountsAQuadraturePairInDegreesAndRefusesABadPart) {
  // A rotator with a quadrature encoder on the motor: 11.7 counts per degree (an SRT-like dish),
  // the index switch at 90°.
  PulseAxisConfig c;
  c.counter.kind = PulseInputKind::Quadrature;
  c.homing.seek_duty = 0.5;
  c.homing.reapproach = false;
  c.homing.stop_s = 0.0;
  c.homing.backoff_s = 0.0;
  c.scale = {PulseUnit::Degrees, 11.7, 90.0};
  PulseAxis axis = PulseAxis::make(c).value();
  EXPECT_EQ(axis.position_deg(10.0).value(), 10.0);  // not homed: unreferenced, from its origin
  // Forward (A leads B) for 4 edges, then the index switch closes: the seek's edge is home.
  axis.start_homing(0.0, false);
  ASSERT_EQ(axis.homing_duty(0.0), 0.5);
  const std::vector<ports::PulseEdge> forward{{ports::PulseLine::QuadratureA, true, 0.01},
                                              {ports::PulseLine::QuadratureB, true, 0.02},
                                              {ports::PulseLine::QuadratureA, false, 0.03},
                                              {ports::PulseLine::QuadratureB, false, 0.04},
                                              {ports::PulseLine::Home, true, 0.05}};
  axis.on_edges(forward);
  EXPECT_EQ(axis.counter().count(), 4);
  EXPECT_NEAR(axis.position_deg(10.0).value(), 10.0 + 4 / 11.7, 1e-12);
  // Stop, back off (B leads A: reverse) until the switch opens, stop: homed at count 4.
  EXPECT_EQ(axis.homing_duty(0.06), -c.homing.slow_duty);  // stop_s 0: backing off at once
  const std::vector<ports::PulseEdge> back{{ports::PulseLine::QuadratureB, true, 0.08},
                                           {ports::PulseLine::Home, false, 0.09},
                                           {ports::PulseLine::QuadratureA, true, 0.10}};
  axis.on_edges(back);
  EXPECT_EQ(axis.counter().count(), 2);
  for (int i = 0; i < 10 && axis.homing_duty(0.2).has_value(); ++i) {
    // the back-off's wait (backoff_s 0), then the stop: homed at the seek's edge
  }
  ASSERT_TRUE(axis.homed()) << axis.homing().reason();
  EXPECT_NEAR(axis.position_deg(10.0).value(), 90.0 - 2 / 11.7, 1e-12);

  PulseAxisConfig bad = c;
  bad.scale.counts_per_unit = 0.0;
  const auto refused = PulseAxis::make(bad);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().message.rfind("pulse scale: ", 0), 0U) << refused.error().message;
}

}  // namespace
}  // namespace azt::control
