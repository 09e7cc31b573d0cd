// The homing state machine (control/homing.hpp) on a toy axis: a count that follows the duty
// (100 counts/s at full duty) and a home switch closed at and below count 0.25, in 50 ms ticks.
// The actuator dish in tests/unit/sim/actuator_dish_test.cpp homes through the real plant.
#include "azt/control/homing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace azt::control {
namespace {

constexpr double kTick = 0.05;

struct ToyAxis {
  double position = 300.5;  ///< in counts
  double switch_at = 0.25;  ///< the switch is closed at and below this
  double counts_per_s = 100.0;
  bool frozen = false;  ///< the motor does not turn (no pulses)
  bool reversed = false;
  bool stuck_switch = false;
  double now_s = 0.0;

  [[nodiscard]] std::int64_t count() const {
    return static_cast<std::int64_t>(std::floor(position));
  }
  [[nodiscard]] bool closed() const { return stuck_switch || position <= switch_at; }

  /// One tick: homing decides, the axis moves, the switch's edge (if any) goes back.
  double tick(Homing& h) {
    const double duty = h.update(now_s, count());
    const bool was_closed = closed();
    if (!frozen) position += (reversed ? -duty : duty) * counts_per_s * kTick;
    now_s += kTick;
    if (closed() != was_closed) h.on_switch(closed(), now_s, count());
    return duty;
  }
};

HomingConfig config() {
  HomingConfig c;
  c.seek_duty = -0.6;
  c.slow_duty = 0.2;
  c.stop_s = 0.5;
  c.backoff_s = 0.5;
  c.phase_timeout_s = 60.0;
  c.max_travel_counts = 2000;
  c.no_pulse_s = 1.0;
  c.tolerance_counts = 1;
  return c;
}

Homing homing(const HomingConfig& c = config()) { return Homing(HomingConfig::make(c).value()); }

/// Runs until homing is no longer active (at most `limit_s`); returns the largest |duty| seen
/// while stopping, which must be 0.
double run(Homing& h, ToyAxis& axis, double limit_s = 120.0) {
  double stopping_duty = 0.0;
  while (h.active() && axis.now_s < limit_s) {
    const bool stopping = h.state() == HomingState::Stopping;
    const double duty = axis.tick(h);
    if (stopping && h.state() == HomingState::Stopping) {
      stopping_duty = std::fmax(stopping_duty, std::fabs(duty));
    }
  }
  return stopping_duty;
}

TEST(HomingConfig, ErrorsNameTheField) {
  EXPECT_TRUE(HomingConfig::make(HomingConfig{}).ok());
  auto c = config();
  c.seek_duty = 0.0;
  EXPECT_EQ(HomingConfig::make(c).error().message, "seek_duty must be non-zero, -1 to 1");
  c = config();
  c.slow_duty = -0.2;
  EXPECT_EQ(HomingConfig::make(c).error().message, "slow_duty must be in (0, 1]");
  c = config();
  c.max_travel_counts = 0;
  EXPECT_EQ(HomingConfig::make(c).error().message, "max_travel_counts must be positive");
  c = config();
  c.no_pulse_s = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(HomingConfig::make(c).error().message.find("no_pulse_s"), std::string::npos);
  c = config();
  c.tolerance_counts = -1;
  EXPECT_NE(HomingConfig::make(c).error().message.find("tolerance_counts"), std::string::npos);
}

TEST(Homing, RefusesTrackingUntilHomedWithTheWords) {
  auto h = homing();
  EXPECT_EQ(h.why_not_homed(), "not homed: homing has not run");
  EXPECT_FALSE(h.counts_from_home(5).has_value());
  EXPECT_EQ(h.update(0.0, 0), 0.0);  // idle homing never drives
  ToyAxis axis;
  h.start(axis.now_s, axis.count(), axis.closed());
  EXPECT_EQ(h.why_not_homed(), "not homed: homing in progress (seeking the home switch)");
  EXPECT_EQ(to_string(h.state()), "seeking");
}

TEST(Homing, SeeksStopsBacksOffAndComesBackSlowly) {
  auto h = homing();
  ToyAxis axis;
  h.start(axis.now_s, axis.count(), axis.closed());
  EXPECT_DOUBLE_EQ(axis.tick(h), -0.6);  // towards the switch at the seek duty
  while (h.state() == HomingState::Seeking) axis.tick(h);
  EXPECT_EQ(h.state(), HomingState::Stopping);
  double duty = 0.0;
  while (h.state() == HomingState::Stopping) {
    duty = axis.tick(h);
    if (h.state() == HomingState::Stopping) {
      EXPECT_EQ(duty, 0.0);
    }
  }
  ASSERT_EQ(h.state(), HomingState::BackingOff);
  EXPECT_DOUBLE_EQ(duty, 0.2);   // away, slowly, from the tick the stop ends
  EXPECT_EQ(run(h, axis), 0.0);  // never driven while stopping
  ASSERT_EQ(h.state(), HomingState::Homed);
  EXPECT_FALSE(h.why_not_homed().has_value());
  EXPECT_EQ(h.last_pass_difference(), 0);
  // The home count is the slow re-approach's edge: the switch point is count 0 from home.
  EXPECT_EQ(h.counts_from_home(axis.count()), 0);
  EXPECT_EQ(h.counts_from_home(axis.count() + 40), 40);
  EXPECT_EQ(h.update(axis.now_s + kTick, axis.count()), 0.0);  // homed: homing wants nothing
}

TEST(Homing, WithoutReapproachTheSeekEdgeIsHome) {
  auto c = config();
  c.reapproach = false;
  auto h = homing(c);
  ToyAxis axis;
  h.start(axis.now_s, axis.count(), axis.closed());
  std::int64_t edge_count = 0;
  while (h.state() == HomingState::Seeking) {
    axis.tick(h);
    edge_count = axis.count();
  }
  run(h, axis);
  ASSERT_EQ(h.state(), HomingState::Homed);
  // Off the switch now (backed off), and counted from the seek's edge.
  EXPECT_FALSE(axis.closed());
  EXPECT_EQ(h.counts_from_home(edge_count), 0);
}

TEST(Homing, StartingOnTheSwitchBacksOffFirst) {
  auto h = homing();
  ToyAxis axis;
  axis.position = -3.5;
  h.start(axis.now_s, axis.count(), axis.closed());
  EXPECT_EQ(h.state(), HomingState::Stopping);
  while (h.state() == HomingState::Stopping) axis.tick(h);
  EXPECT_EQ(h.state(), HomingState::BackingOff);
  EXPECT_GT(axis.tick(h), 0.0);
  run(h, axis);
  EXPECT_EQ(h.state(), HomingState::Homed);
}

TEST(Homing, SeekTimeoutFailsWithTheReason) {
  auto c = config();
  c.phase_timeout_s = 5.0;
  auto h = homing(c);
  ToyAxis axis;
  axis.switch_at = -1e9;  // the switch is never met
  h.start(axis.now_s, axis.count(), axis.closed());
  run(h, axis);
  ASSERT_EQ(h.state(), HomingState::Failed);
  EXPECT_EQ(h.why_not_homed(),
            "not homed: homing failed: seeking the home switch: gave up after 5 s without the "
            "home switch");
  EXPECT_NEAR(axis.now_s, 5.05, 0.06);
  EXPECT_EQ(h.update(axis.now_s, axis.count()), 0.0);
}

TEST(Homing, TravelBeyondTheLimitFails) {
  auto c = config();
  c.max_travel_counts = 100;
  auto h = homing(c);
  ToyAxis axis;
  axis.switch_at = -1e9;
  h.start(axis.now_s, axis.count(), axis.closed());
  run(h, axis);
  ASSERT_EQ(h.state(), HomingState::Failed);
  EXPECT_EQ(h.reason(),
            "seeking the home switch: travelled 102 counts without the home switch "
            "(max_travel_counts 100)");
}

TEST(Homing, NoPulsesWhileDrivenFails) {
  auto h = homing();
  ToyAxis axis;
  axis.frozen = true;  // the actuator's own end switch cut the motor, or the reed is broken
  h.start(axis.now_s, axis.count(), axis.closed());
  run(h, axis);
  ASSERT_EQ(h.state(), HomingState::Failed);
  EXPECT_EQ(h.reason().rfind("seeking the home switch: no pulses for 1.", 0), 0U) << h.reason();
  EXPECT_LT(axis.now_s, 1.2);
}

TEST(Homing, CountingTheWrongWayFails) {
  // A quadrature sensor (or motor) wired the other way round: the count rises while seeking down.
  auto h = homing();
  ToyAxis axis;
  axis.reversed = true;
  h.start(axis.now_s, axis.count(), axis.closed());
  run(h, axis);
  ASSERT_EQ(h.state(), HomingState::Failed);
  EXPECT_EQ(h.reason(),
            "seeking the home switch: counted 9 counts the wrong way (a motor or a sensor wired "
            "the other way round)");
}

TEST(Homing, StuckSwitchWhileBackingOffFails) {
  auto c = config();
  c.phase_timeout_s = 3.0;
  c.max_travel_counts = 100000;
  auto h = homing(c);
  ToyAxis axis;
  axis.stuck_switch = true;
  h.start(axis.now_s, axis.count(), axis.closed());
  run(h, axis);
  ASSERT_EQ(h.state(), HomingState::Failed);
  EXPECT_EQ(h.reason(),
            "backing off the home switch: gave up after 3 s with the home switch still closed (a "
            "stuck switch or its wiring)");
}

Homing homed_at_zero(ToyAxis& axis) {
  auto h = homing();
  h.start(axis.now_s, axis.count(), axis.closed());
  run(h, axis);
  EXPECT_EQ(h.state(), HomingState::Homed);
  return h;
}

TEST(Homing, PassWithinToleranceStaysHomed) {
  ToyAxis axis;
  auto h = homed_at_zero(axis);
  const std::int64_t home = axis.count() - *h.counts_from_home(axis.count());
  h.on_switch(false, axis.now_s + 1.0, home + 50);
  h.on_switch(true, axis.now_s + 2.0, home + 1);  // one count off: within the tolerance
  EXPECT_EQ(h.state(), HomingState::Homed);
  EXPECT_EQ(h.last_pass_difference(), 1);
}

TEST(Homing, MissedPulsesAtAPassLatchPositionLost) {
  ToyAxis axis;
  auto h = homed_at_zero(axis);
  const std::int64_t home = axis.count() - *h.counts_from_home(axis.count());
  h.on_switch(false, axis.now_s + 1.0, home + 50);
  h.on_switch(true, axis.now_s + 9.0, home + 3);  // the count says 3 above home, at home
  ASSERT_EQ(h.state(), HomingState::PositionLost);
  EXPECT_EQ(h.last_pass_difference(), 3);
  EXPECT_EQ(h.reason(), "position lost: 3 counts lost (the home switch closed at count " +
                            std::to_string(home + 3) + ", homing found it at " +
                            std::to_string(home) + "; tolerance 1)");
  EXPECT_EQ(h.why_not_homed(), "not homed: " + h.reason() + "; home again");
  EXPECT_FALSE(h.counts_from_home(home).has_value());
  // Latched: a later good pass does not clear it; the operator's reset does (home again).
  h.on_switch(true, axis.now_s + 20.0, home);
  EXPECT_EQ(h.state(), HomingState::PositionLost);
  h.reset();
  EXPECT_EQ(h.why_not_homed(), "not homed: homing has not run");
}

TEST(Homing, AbortStopsWithTheReason) {
  auto h = homing();
  ToyAxis axis;
  h.start(axis.now_s, axis.count(), axis.closed());
  axis.tick(h);
  h.abort("STOP from the console");
  EXPECT_EQ(h.state(), HomingState::NotHomed);
  EXPECT_EQ(h.why_not_homed(), "not homed: homing stopped: STOP from the console");
  EXPECT_EQ(axis.tick(h), 0.0);
}

TEST(Homing, BadTimeFailsAnActiveHoming) {
  auto h = homing();
  ToyAxis axis;
  h.start(10.0, axis.count(), axis.closed());
  EXPECT_NE(h.update(10.05, axis.count()), 0.0);
  EXPECT_EQ(h.update(9.0, axis.count()), 0.0);
  EXPECT_EQ(h.state(), HomingState::Failed);
  EXPECT_EQ(h.reason(), "homing stopped: the time went backwards or is not a number");
  h.start(std::numeric_limits<double>::quiet_NaN(), 0, false);
  EXPECT_EQ(h.state(), HomingState::Failed);
}

}  // namespace
}  // namespace azt::control
