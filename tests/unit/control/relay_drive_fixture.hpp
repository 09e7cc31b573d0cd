#pragma once
// The relay drive settings the relay tests share (tests/unit/control/relay_drive_test.cpp,
// relay_drive_closed_loop_test.cpp, power_polarity_relays_test.cpp): a 20 Hz tick, seed 002's
// 10-bit pot, binary-exact times, and a drive settled at rest.

#include <gtest/gtest.h>

#include <limits>

#include "azt/control/relay_drive.hpp"

namespace azt::control::relay_test {

using Cmd = RelayCommand;

inline constexpr double kTick = 0.05;             // 20 Hz control tick
inline constexpr double kLsb10 = 360.0 / 1024.0;  // seed 002: "360/1024 or 0.35 degree"
inline constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

inline RelayDriveConfig config() {
  RelayDriveConfig c;
  c.window_deg = 1.0;
  c.lsb_deg = kLsb10;
  c.coast_deg = 0.0;
  c.min_on_s = 0.25;  // binary-exact times keep the boundary checks exact
  c.reversal_dead_s = 0.5;
  c.min_off_s = 0.0;
  c.lead = true;
  return c;
}

/// A drive that has been ticking at rest long enough for the start-up dead time to be over:
/// its next tick is at t = 10 s.
inline RelayDrive settled(const RelayDriveConfig& c) {
  RelayDrive d(c);
  EXPECT_EQ(d.update(100.0, 100.0, 0.0), Cmd::Off);
  EXPECT_EQ(d.update(100.0, 100.0, 9.95), Cmd::Off);
  return d;
}

}  // namespace azt::control::relay_test
