// The power + polarity relays of seed 002's elevation actuator in virtual time: the polarity never
// moves under power or within the dead time, as worked examples and as a seeded random property
// over arbitrary command sequences.
#include "azt/control/relay_drive.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <random>

#include "control/relay_drive_fixture.hpp"

namespace azt::control {
namespace {

using relay_test::Cmd;
using relay_test::config;
using relay_test::kNan;
using relay_test::kTick;
using relay_test::settled;

PowerPolarityConfig pp_config() {
  PowerPolarityConfig c;
  c.dead_s = 0.5;
  c.settle_s = 0.0625;  // binary-exact, as the test times at the boundaries
  return c;
}

TEST(PowerPolarityConfig, Validates) {
  EXPECT_TRUE(PowerPolarityConfig::make(pp_config()).ok());
  auto c = pp_config();
  c.dead_s = 0.0;
  EXPECT_FALSE(PowerPolarityConfig::make(c).ok());
  c = pp_config();
  c.settle_s = -0.01;
  EXPECT_FALSE(PowerPolarityConfig::make(c).ok());
  c = pp_config();
  c.settle_s = kNan;
  EXPECT_FALSE(PowerPolarityConfig::make(c).ok());
}

TEST(PowerPolarityRelays, ForwardThenReverse) {
  PowerPolarityRelays r(pp_config());
  using PP = PowerPolarity;
  EXPECT_EQ(r.update(Cmd::Forward, 0.0), (PP{false, false}));  // settle after start-up
  EXPECT_EQ(r.update(Cmd::Forward, 0.0625), (PP{true, false}));
  EXPECT_EQ(r.update(Cmd::Off, 1.0), (PP{false, false}));       // power opens at 1.0
  EXPECT_EQ(r.update(Cmd::Reverse, 1.25), (PP{false, false}));  // dead time not over
  EXPECT_EQ(r.update(Cmd::Reverse, 1.5), (PP{false, true}));    // polarity moves, power open
  EXPECT_EQ(r.update(Cmd::Reverse, 1.5), (PP{false, true}));    // not on the same instant …
  EXPECT_EQ(r.update(Cmd::Reverse, 1.5625), (PP{true, true}));  // … but settle_s later
  // A command against the present polarity opens power at once (never drives the wrong way).
  EXPECT_EQ(r.update(Cmd::Forward, 1.625), (PP{false, true}));
  EXPECT_EQ(r.update(Cmd::Forward, 2.0), (PP{false, true}));
  EXPECT_EQ(r.update(Cmd::Forward, 2.125), (PP{false, false}));
  EXPECT_EQ(r.update(Cmd::Forward, 2.1875), (PP{true, false}));
  r.halt(2.25);  // the dead time runs from the halt
  EXPECT_EQ(r.output(), (PP{false, false}));
  EXPECT_EQ(r.update(Cmd::Reverse, 2.5), (PP{false, false}));
  EXPECT_EQ(r.update(Cmd::Reverse, 2.75), (PP{false, true}));
}

TEST(PowerPolarityRelays, FollowsTheRelayDriveAfterItsDeadTime) {
  RelayDrive d = settled(config());
  PowerPolarityRelays r(pp_config());
  r.update(Cmd::Off, 9.95);
  std::optional<double> reversed_at;
  std::optional<double> powered_reverse_at;
  for (long k = 0; k < 200; ++k) {
    const double now = 10.0 + static_cast<double>(k) * kTick;
    const double target = now < 11.0 ? 105.0 : 90.0;  // forward, then back
    const double position = now < 11.0 ? 100.0 : 105.0;
    const PowerPolarity out = r.update(d.update(target, position, now), now);
    if (out.reverse && !reversed_at) reversed_at = now;
    if (out.reverse && out.power && !powered_reverse_at) powered_reverse_at = now;
  }
  ASSERT_TRUE(reversed_at && powered_reverse_at);
  // Forward ran 10.0–11.0 (released when the target jumped behind). The drive's Reverse and the
  // polarity change coincide after its dead time; power closes settle_s (two ticks) later.
  EXPECT_NEAR(*reversed_at, 11.5, 1e-9);
  EXPECT_NEAR(*powered_reverse_at, 11.6, 1e-9);  // the first tick ≥ settle_s later
}

TEST(PowerPolarityRelays, InvalidTimeOpensPowerAndRestartsTheDeadTime) {
  PowerPolarityRelays r(pp_config());
  r.update(Cmd::Forward, 0.0);
  ASSERT_TRUE(r.update(Cmd::Forward, 0.1).power);
  EXPECT_FALSE(r.update(Cmd::Forward, kNan).power);
  EXPECT_FALSE(r.update(Cmd::Reverse, 5.0).reverse);  // off since 5.0, not since the NaN
  EXPECT_FALSE(r.update(Cmd::Reverse, 5.45).reverse);
  EXPECT_TRUE(r.update(Cmd::Reverse, 5.5).reverse);
  EXPECT_TRUE(r.update(Cmd::Reverse, 5.5625).power);
  EXPECT_FALSE(r.update(Cmd::Reverse, 1.0).power);  // backwards
}

// Seeded random property over arbitrary command sequences (not only RelayDrive's): the polarity
// never moves with power on or within dead_s of power opening; power never closes on the tick the
// polarity moved nor within settle_s of it; power on always drives the commanded way; and a
// command held long enough is obeyed.
TEST(PowerPolarityRelays, PolarityNeverChangesUnderPowerForRandomCommands) {
  const PowerPolarityConfig c = pp_config();
  PowerPolarityRelays r(c);
  std::mt19937_64 rng(0x9014a41e);
  std::uniform_real_distribution<double> dt_s(0.005, 0.1);
  std::uniform_int_distribution<int> pick(0, 2);
  std::uniform_int_distribution<int> hold_ticks(1, 40);
  const Cmd commands[] = {Cmd::Off, Cmd::Forward, Cmd::Reverse};
  double now = 0.0;
  PowerPolarity previous = r.output();
  double off_since = 0.0;  // power is taken to have been on until the first tick
  double polarity_since = 0.0;
  Cmd cmd = Cmd::Off;
  double cmd_since = 0.0;
  int remaining_ticks = 0;
  int polarity_changes = 0;
  for (int k = 0; k < 300000; ++k) {
    now += dt_s(rng);
    if (k == 0) off_since = polarity_since = now;
    if (remaining_ticks-- <= 0) {
      const Cmd next = commands[pick(rng)];
      if (next != cmd) cmd_since = now;
      cmd = next;
      remaining_ticks = hold_ticks(rng);
    }
    const PowerPolarity out = r.update(cmd, now);
    if (out.reverse != previous.reverse) {
      ++polarity_changes;
      ASSERT_FALSE(previous.power) << "tick " << k;
      ASSERT_FALSE(out.power) << "tick " << k;
      ASSERT_GE(now - off_since, c.dead_s) << "tick " << k;
      polarity_since = now;
    }
    if (out.power) {
      ASSERT_NE(cmd, Cmd::Off) << "tick " << k;
      ASSERT_EQ(out.reverse, cmd == Cmd::Reverse) << "tick " << k;
      if (!previous.power) {
        ASSERT_LT(polarity_since, now) << "tick " << k;
        ASSERT_GE(now - polarity_since, c.settle_s) << "tick " << k;
      }
    } else if (previous.power) {
      off_since = now;
    }
    // Liveness: a command held for dead + settle + two of the longest ticks is obeyed.
    if (cmd != Cmd::Off && now - cmd_since >= c.dead_s + c.settle_s + 0.2) {
      ASSERT_TRUE(out.power) << "tick " << k;
    }
    previous = out;
  }
  EXPECT_GT(polarity_changes, 1000);
}

}  // namespace
}  // namespace azt::control
