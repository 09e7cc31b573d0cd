// The on/off relay drive (seed 002: CW/CCW relays on the azimuth rotor) in virtual time: its
// settings, tick by tick, and as a seeded random property. Timing references: reference/
// reliability-and-security.md §1.8 and test R19 (on-pulses ≥ 100 ms, reversal ≥ 500 ms).
#include "azt/control/relay_drive.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "control/relay_drive_fixture.hpp"

namespace azt::control {
namespace {

using relay_test::Cmd;
using relay_test::config;
using relay_test::kLsb10;
using relay_test::kNan;
using relay_test::kTick;
using relay_test::settled;

TEST(RelayDriveConfig, Validates) {
  EXPECT_TRUE(RelayDriveConfig::make(config()).ok());
  EXPECT_TRUE(RelayDriveConfig::make(RelayDriveConfig{}).ok());  // the defaults are usable
  auto c = config();
  c.window_deg = 10.5;
  EXPECT_FALSE(RelayDriveConfig::make(c).ok());
  c = config();
  c.lsb_deg = 0.0;
  EXPECT_FALSE(RelayDriveConfig::make(c).ok());
  c = config();
  c.coast_deg = -0.1;
  EXPECT_FALSE(RelayDriveConfig::make(c).ok());
  c = config();
  c.min_on_s = kNan;
  EXPECT_FALSE(RelayDriveConfig::make(c).ok());
  c = config();
  c.reversal_dead_s = 0.0;  // a reversal must always have a dead time
  const auto r = RelayDriveConfig::make(c);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("reversal_dead_s"), std::string::npos);
  c = config();
  c.min_off_s = -1.0;
  EXPECT_FALSE(RelayDriveConfig::make(c).ok());
}

TEST(RelayCommand, Names) {
  EXPECT_EQ(to_string(Cmd::Off), "off");
  EXPECT_EQ(to_string(Cmd::Forward), "forward");
  EXPECT_EQ(to_string(Cmd::Reverse), "reverse");
}

TEST(RelayDrive, FirstStartWaitsTheDeadTimeAfterConstruction) {
  // A restart after a crash may find the motor still turning: the first start waits.
  RelayDrive d(config());
  EXPECT_EQ(d.update(110.0, 100.0, 1000.0), Cmd::Off);
  EXPECT_EQ(d.update(110.0, 100.0, 1000.45), Cmd::Off);
  EXPECT_EQ(d.update(110.0, 100.0, 1000.5), Cmd::Forward);
  EXPECT_EQ(d.starts(), 1u);
}

TEST(RelayDrive, NoStartInsideL2) {
  const double l2 = 1.0 + kLsb10;  // window + 1 LSB
  RelayDrive d = settled(config());
  EXPECT_EQ(d.update(100.0 + 0.999 * l2, 100.0, 10.0), Cmd::Off);
  EXPECT_EQ(d.update(100.0 - 0.999 * l2, 100.0, 10.05), Cmd::Off);
  EXPECT_EQ(d.update(100.0 + l2, 100.0, 10.1), Cmd::Off);  // "≤ L2" still rests
  EXPECT_EQ(d.starts(), 0u);
  EXPECT_EQ(d.update(100.0 + 1.001 * l2, 100.0, 10.15), Cmd::Forward);
  EXPECT_EQ(d.starts(), 1u);

  RelayDrive back = settled(config());
  EXPECT_EQ(back.update(100.0 - 1.001 * l2, 100.0, 10.0), Cmd::Reverse);
}

TEST(RelayDrive, StopsWithinOneLsbOfTheGoal) {
  RelayDrive d = settled(config());
  ASSERT_EQ(d.update(105.0, 100.0, 10.0), Cmd::Forward);
  EXPECT_EQ(d.update(105.0, 103.0, 10.5), Cmd::Forward);
  EXPECT_EQ(d.update(105.0, 105.0 - 1.1 * kLsb10, 10.55), Cmd::Forward);
  EXPECT_EQ(d.update(105.0, 105.0 - 0.9 * kLsb10, 10.6), Cmd::Off);
  // At rest again inside L2: no restart.
  EXPECT_EQ(d.update(105.0, 105.0 - 0.9 * kLsb10, 20.0), Cmd::Off);
  EXPECT_EQ(d.starts(), 1u);
}

TEST(RelayDrive, StopsWhenTheErrorChangesSign) {
  // A reading jump (or a target that jumped back) puts the axis past its goal: release, and the
  // releasing tick is Off, not Reverse.
  RelayDrive d = settled(config());
  ASSERT_EQ(d.update(105.0, 100.0, 10.0), Cmd::Forward);
  EXPECT_EQ(d.update(105.0, 108.0, 10.5), Cmd::Off);
}

TEST(RelayDrive, ReleasesEarlyByTheCoastDistance) {
  auto c = config();
  c.coast_deg = 1.2;
  RelayDrive d = settled(c);
  ASSERT_EQ(d.update(105.0, 100.0, 10.0), Cmd::Forward);
  EXPECT_EQ(d.update(105.0, 105.0 - 1.2 - 1.1 * kLsb10, 10.5), Cmd::Forward);
  EXPECT_EQ(d.update(105.0, 105.0 - 1.2 - 0.9 * kLsb10, 10.55), Cmd::Off);
}

TEST(RelayDrive, LeadsAMovingTargetByTheWindow) {
  RelayDrive d = settled(config());
  const double rate = 15.0 / 3600.0;  // the Moon in azimuth
  ASSERT_EQ(d.update(102.0, 100.0, 10.0, rate), Cmd::Forward);
  // Past the target, short of target + window: still running …
  EXPECT_EQ(d.update(102.0, 103.0 - 1.1 * kLsb10, 10.5, rate), Cmd::Forward);
  // … released within 1 LSB of target + 1°.
  EXPECT_EQ(d.update(102.0, 103.0 - 0.9 * kLsb10, 10.55, rate), Cmd::Off);
  // Without the rate (or with lead off) the goal is the target itself.
  RelayDrive fixed = settled(config());
  ASSERT_EQ(fixed.update(102.0, 100.0, 10.0), Cmd::Forward);
  EXPECT_EQ(fixed.update(102.0, 102.0 - 0.9 * kLsb10, 10.5), Cmd::Off);
}

TEST(RelayDrive, MinimumOnTimeHoldsEvenWhenTheGoalIsReachedEarly) {
  // Consequence (documented in the header): the axis runs on for the rest of min_on_s and then
  // coasts, even past the goal — which is why the window should exceed rate × min_on_s.
  RelayDrive d = settled(config());  // min_on_s = 0.25
  ASSERT_EQ(d.update(101.5, 100.0, 10.0), Cmd::Forward);
  EXPECT_EQ(d.update(101.5, 101.5, 10.05), Cmd::Forward);  // at the goal
  EXPECT_EQ(d.update(101.5, 102.0, 10.1), Cmd::Forward);   // past it
  EXPECT_EQ(d.update(101.5, 102.5, 10.2), Cmd::Forward);
  EXPECT_EQ(d.update(101.5, 103.0, 10.25), Cmd::Off);  // 0.25 s on
}

TEST(RelayDrive, ReversalWaitsTheDeadTimeWithBothOff) {
  RelayDrive d = settled(config());  // reversal_dead_s = 0.5
  ASSERT_EQ(d.update(105.0, 100.0, 10.0), Cmd::Forward);
  ASSERT_EQ(d.update(105.0, 105.0, 11.0), Cmd::Off);  // released at 11.0
  // The target jumps far the other way: both relays stay open for 0.5 s.
  for (int k = 1; k <= 9; ++k) {  // 11.05 … 11.45
    const double t = 11.0 + k * kTick;
    EXPECT_EQ(d.update(90.0, 105.0, t), Cmd::Off) << "t = " << t;
  }
  EXPECT_EQ(d.update(90.0, 105.0, 11.5), Cmd::Reverse);
  EXPECT_EQ(d.starts(), 2u);
  EXPECT_EQ(d.reversals(), 1u);
}

TEST(RelayDrive, SameDirectionRestartNeedsOnlyMinOff) {
  auto c = config();
  c.min_off_s = 2.0;
  RelayDrive d = settled(c);
  ASSERT_EQ(d.update(105.0, 100.0, 10.0), Cmd::Forward);
  ASSERT_EQ(d.update(105.0, 105.0, 11.0), Cmd::Off);
  EXPECT_EQ(d.update(110.0, 105.0, 12.95), Cmd::Off);
  EXPECT_EQ(d.update(110.0, 105.0, 13.0), Cmd::Forward);
  EXPECT_EQ(d.reversals(), 0u);

  RelayDrive z = settled(config());  // min_off_s = 0: the next tick may restart
  ASSERT_EQ(z.update(105.0, 100.0, 10.0), Cmd::Forward);
  ASSERT_EQ(z.update(105.0, 105.0, 11.0), Cmd::Off);
  EXPECT_EQ(z.update(110.0, 105.0, 11.05), Cmd::Forward);
}

TEST(RelayDrive, HaltOverridesTheMinimumOnTimeButNotTheDeadTime) {
  RelayDrive d = settled(config());
  ASSERT_EQ(d.update(105.0, 100.0, 10.0), Cmd::Forward);
  d.halt(10.05);  // well inside min_on_s
  EXPECT_EQ(d.command(), Cmd::Off);
  EXPECT_EQ(d.update(90.0, 100.1, 10.1), Cmd::Off);
  EXPECT_EQ(d.update(90.0, 100.1, 10.5), Cmd::Off);
  EXPECT_EQ(d.update(90.0, 100.1, 10.55), Cmd::Reverse);  // 0.5 s after the halt
  // Halting an idle drive changes nothing.
  RelayDrive idle = settled(config());
  idle.halt(10.0);
  EXPECT_EQ(idle.update(105.0, 100.0, 10.05), Cmd::Forward);
}

TEST(RelayDrive, InvalidInputsReleaseAtOnce) {
  RelayDrive d = settled(config());
  ASSERT_EQ(d.update(105.0, 100.0, 10.0), Cmd::Forward);
  EXPECT_EQ(d.update(105.0, kNan, 10.05), Cmd::Off);      // inside min_on_s: safety first
  EXPECT_EQ(d.update(105.0, 100.0, 10.1), Cmd::Forward);  // same direction, min_off_s = 0

  // A non-finite time: released, and the dead time runs from the next valid tick.
  ASSERT_EQ(d.update(90.0, 100.0, 10.15), Cmd::Forward);  // still inside min_on_s
  EXPECT_EQ(d.update(90.0, 100.0, kNan), Cmd::Off);
  EXPECT_EQ(d.update(90.0, 100.0, 20.0), Cmd::Off);  // the release time is taken here
  EXPECT_EQ(d.update(90.0, 100.0, 20.45), Cmd::Off);
  EXPECT_EQ(d.update(90.0, 100.0, 20.5), Cmd::Reverse);

  // Time running backwards releases and restarts the waits in the new time base.
  EXPECT_EQ(d.update(90.0, 100.0, 5.0), Cmd::Off);
  EXPECT_EQ(d.update(110.0, 100.0, 5.45), Cmd::Off);
  EXPECT_EQ(d.update(110.0, 100.0, 5.5), Cmd::Forward);
  EXPECT_EQ(d.update(110.0, 100.0, 5.55, std::numeric_limits<double>::infinity()), Cmd::Off);
}

// Seeded random property: whatever the targets, readings and tick spacing, the timing rules hold.
TEST(RelayDrive, TimingRulesHoldForRandomInputs) {
  auto c = config();
  c.min_off_s = 0.3;
  RelayDrive d(c);
  std::mt19937_64 rng(0x7e1a7d21);
  std::uniform_real_distribution<double> dt_s(0.01, 0.2);
  std::uniform_real_distribution<double> jump_deg(-5.0, 5.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double now = 0.0;
  double target = 100.0;
  double position = 100.0;
  Cmd previous = Cmd::Off;
  Cmd last_direction = Cmd::Off;
  double first_tick = 0.0;
  double on_since = 0.0;
  std::optional<double> released_at;
  int starts = 0;
  for (int k = 0; k < 200000; ++k) {
    now += dt_s(rng);
    if (unit(rng) < 0.02) target += jump_deg(rng);
    if (previous == Cmd::Forward) position += 0.3 * unit(rng);
    if (previous == Cmd::Reverse) position -= 0.3 * unit(rng);
    position += 0.1 * (unit(rng) - 0.5);  // reading noise
    Cmd cmd;
    const bool halted = unit(rng) < 0.001;
    if (halted) {
      d.halt(now);
      cmd = d.command();
    } else {
      cmd = d.update(target, position, now);
    }
    if (k == 0) first_tick = now;
    ASSERT_FALSE(previous == Cmd::Forward && cmd == Cmd::Reverse) << "tick " << k;
    ASSERT_FALSE(previous == Cmd::Reverse && cmd == Cmd::Forward) << "tick " << k;
    if (previous != Cmd::Off && cmd == Cmd::Off) {
      if (!halted) {
        ASSERT_GE(now - on_since, c.min_on_s) << "tick " << k;
      }
      released_at = now;
    }
    if (previous == Cmd::Off && cmd != Cmd::Off) {
      ++starts;
      const double since = now - released_at.value_or(first_tick);
      ASSERT_GE(since, c.min_off_s) << "tick " << k;
      if (cmd != last_direction) {
        ASSERT_GE(since, c.reversal_dead_s) << "tick " << k;
      }
      on_since = now;
      last_direction = cmd;
    }
    previous = cmd;
  }
  EXPECT_EQ(d.starts(), static_cast<std::uint64_t>(starts));
  EXPECT_GT(starts, 1000);  // the property was exercised, not vacuously true
  EXPECT_GT(d.reversals(), 100u);
}

}  // namespace
}  // namespace azt::control
