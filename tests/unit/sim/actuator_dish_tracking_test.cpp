// A pulse-counted actuator dish flown by the core's pieces in virtual time, wired the way a
// DrivenAxis will wire them (the plug-in points in each header): the plant's reed pulses and
// home-switch edges, in time order, into PulseCounter and Homing; homing's duty until homed;
// then the position from PulseScale through the worked example's triangle (docs/hardware.md,
// "Linear actuators") into AxisController. The dish homes, follows a slow elevation ramp, and a
// pulse dropped on the way is caught at the next pass of the home switch, while the same run
// without the drop passes it clean.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "azt/control/axis_controller.hpp"
#include "azt/control/homing.hpp"
#include "azt/control/pulse_counter.hpp"
#include "azt/control/pulse_scale.hpp"
#include "azt/sim/actuator_dish_plant.hpp"

namespace azt::sim {
namespace {

constexpr double kTick = 0.02;           // a 50 Hz control loop
constexpr double kHomeSwitchMm = 525.0;  // between the reed's pulses at 524.5 and 525.5 mm

ActuatorDishParams dish() {
  ActuatorDishParams p;
  p.geometry.pivot_to_fixed_mm = 650.0;
  p.geometry.pivot_to_moving_mm = 400.0;
  p.geometry.offset_deg = 48.0;
  p.geometry.retracted_mm = 520.0;
  p.geometry.extended_mm = 977.2;
  p.speed_mm_s = 8.0;
  p.time_constant_s = 0.15;
  p.stiction_duty = 0.1;
  p.pulses_per_mm = 1.0;
  p.pulse_phase = 0.5;
  p.home_switch_mm = kHomeSwitchMm;
  p.start_mm = 700.0;
  return p;
}

control::HomingConfig homing_config() {
  control::HomingConfig c;
  c.seek_duty = -0.8;  // the switch is at the retracted (low) end
  c.slow_duty = 0.3;
  c.stop_s = 0.5;
  c.backoff_s = 1.0;
  c.phase_timeout_s = 120.0;
  c.max_travel_counts = 600;  // the whole stroke is 457 pulses
  c.no_pulse_s = 2.0;
  c.tolerance_counts = 0;  // the simulated switch makes at exactly the same length every time
  return c;
}

control::AxisControlConfig controller_config(double lsb_deg) {
  control::AxisControlConfig c;
  c.window_deg = 0.2;
  c.lsb_deg = lsb_deg;     // the coarsest count: 1 mm at the extended end
  c.max_rate_deg_s = 2.5;  // the fastest the axis goes (8 mm/s at 0.31°/mm): never overshoots
  c.ramp_s = 0.5;
  c.min_duty = 0.1;
  c.time_constant_s = 0.15;
  return control::AxisControlConfig::make(c).value();
}

control::DriveDirection direction_of(double duty) {
  if (duty > 0.0) return control::DriveDirection::Forward;
  if (duty < 0.0) return control::DriveDirection::Reverse;
  return control::DriveDirection::Stopped;
}

/// The plant and the core's pieces, one tick at a time.
struct PulsedDish {
  ActuatorDishPlant plant = ActuatorDishPlant::make(dish()).value();
  control::PulseCounter counter{control::PulseCounterConfig::make({}).value()};
  control::Homing homing{control::HomingConfig::make(homing_config()).value()};
  control::PulseScale scale =
      control::PulseScale::make({control::PulseUnit::Millimetres, 1.0, kHomeSwitchMm},
                                plant.geometry())
          .value();
  control::AxisController controller{controller_config(scale.max_deg_per_count())};
  std::vector<ActuatorEvent> pending;  ///< the plant's events of the last step
  std::optional<std::string> sensor_fault;

  void feed(const ActuatorEvent& e) {
    switch (e.kind) {
      case ActuatorEventKind::Pulse:
        counter.on_pulse(e.at_s);
        return;
      case ActuatorEventKind::HomeClosed:
      case ActuatorEventKind::HomeOpened:
        homing.on_switch(e.kind == ActuatorEventKind::HomeClosed, e.at_s, counter.count());
        return;
    }
  }

  [[nodiscard]] std::optional<double> position_deg() const {
    const auto from_home = homing.counts_from_home(counter.count());
    if (!from_home) return std::nullopt;
    const auto angle = scale.angle_deg(*from_home);
    return angle ? std::optional<double>(*angle) : std::nullopt;
  }

  double decide(std::optional<double> target_deg, double rate_deg_s) {
    const double now_s = plant.now_s();
    const double homing_duty = homing.update(now_s, counter.count());
    if (homing.active()) return homing_duty;
    if (!homing.homed() || !target_deg) {
      controller.halt();
      return 0.0;
    }
    const auto angle = scale.angle_deg(*homing.counts_from_home(counter.count()));
    if (!angle) {
      sensor_fault = angle.error().message;
      controller.halt();
      return 0.0;
    }
    return controller.update(*target_deg, *angle, rate_deg_s, kTick);
  }

  void tick(std::optional<double> target_deg = std::nullopt, double rate_deg_s = 0.0) {
    for (const auto& e : pending) feed(e);
    const double duty = decide(target_deg, rate_deg_s);
    counter.set_drive(direction_of(duty), plant.now_s());
    pending = plant.step(duty, kTick);
  }

  void home() {
    homing.start(plant.now_s(), counter.count(), plant.home_closed());
    while (homing.active() && plant.now_s() < 300.0) tick();
  }

  /// Holds `target_deg` for `seconds`.
  void hold(double target_deg, double seconds) {
    const double end_s = plant.now_s() + seconds;
    while (plant.now_s() < end_s) tick(target_deg);
  }
};

TEST(ActuatorDishTracking, HomesToTheSwitchAtTheRetractedEnd) {
  PulsedDish d;
  EXPECT_EQ(d.homing.why_not_homed(), "not homed: homing has not run");
  d.home();
  ASSERT_EQ(d.homing.state(), control::HomingState::Homed) << d.homing.reason();
  // 175 mm at the seek's 6.2 mm/s, then the back-off and the slow return: well under a minute.
  EXPECT_LT(d.plant.now_s(), 60.0);
  EXPECT_EQ(d.counter.ambiguous(), 0U);
  // Settled: the counted angle is the true one within one count (0.144° at this end).
  d.hold(d.position_deg().value(), 2.0);
  EXPECT_NEAR(d.position_deg().value(), d.plant.angle_deg(), d.scale.deg_per_count(0));
}

/// Homes, slews to 20° and follows 20° → 30° at 0.02°/s (a slow pass); returns the largest
/// |true angle − target| during the ramp.
double ramp(PulsedDish& d, std::optional<double> drop_pulse_at_s = std::nullopt) {
  d.home();
  EXPECT_TRUE(d.homing.homed()) << d.homing.reason();
  d.hold(20.0, 30.0);
  const double rate_deg_s = 0.02;
  const double start_s = d.plant.now_s();
  if (drop_pulse_at_s) d.plant.drop_pulse_after(start_s + *drop_pulse_at_s);
  double worst_deg = 0.0;
  while (d.plant.now_s() < start_s + 500.0) {
    const double target = 20.0 + rate_deg_s * (d.plant.now_s() - start_s);
    d.tick(target, rate_deg_s);
    worst_deg = std::max(worst_deg, std::fabs(d.plant.angle_deg() - target));
  }
  return worst_deg;
}

/// Parks low: 521 mm, 4 mm past the home switch's make point (the controller stops within one
/// count, 0.3°, of its goal, so a park any nearer the switch might stop short of it).
void stow(PulsedDish& d) {
  const double stow_deg = d.plant.geometry().angle_deg(521.0).value();
  d.hold(stow_deg, 80.0);
}

TEST(ActuatorDishTracking, FollowsASlowElevationRamp) {
  PulsedDish d;
  const double worst_deg = ramp(d);
  // The bound: the start threshold L2 = window + one count at the coarse end (0.51°), plus one
  // count here (0.16°) for the counted position's own step.
  const double bound_deg = d.controller.config().start_threshold_deg() + d.scale.deg_per_count(230);
  EXPECT_LE(worst_deg, bound_deg);
  EXPECT_FALSE(d.sensor_fault.has_value());
  EXPECT_NEAR(d.plant.angle_deg(), 30.0, bound_deg);
  RecordProperty("max_error_deg", std::to_string(worst_deg));
}

TEST(ActuatorDishTracking, PassesTheHomeSwitchCleanWithoutADroppedPulse) {
  PulsedDish d;
  ramp(d);
  stow(d);
  EXPECT_TRUE(d.plant.home_closed());
  EXPECT_EQ(d.homing.state(), control::HomingState::Homed) << d.homing.reason();
  EXPECT_EQ(d.homing.last_pass_difference(), 0);
}

TEST(ActuatorDishTracking, DetectsADroppedPulseAtTheNextHomePass) {
  PulsedDish d;
  ramp(d, /*drop_pulse_at_s=*/250.0);
  EXPECT_EQ(d.plant.pulses_dropped(), 1U);
  EXPECT_TRUE(d.homing.homed());  // nothing can tell yet
  stow(d);
  ASSERT_EQ(d.homing.state(), control::HomingState::PositionLost);
  EXPECT_EQ(d.homing.last_pass_difference(), -1);
  EXPECT_EQ(d.homing.reason().rfind("position lost: 1 count lost (the home switch closed at", 0),
            0U)
      << d.homing.reason();
  EXPECT_EQ(d.homing.why_not_homed()->rfind("not homed: position lost", 0), 0U);
}

}  // namespace
}  // namespace azt::sim
