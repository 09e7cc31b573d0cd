// The control loop closed around the simulated antenna (plants, EncoderHub frames, decoder,
// supervisor, controller) in virtual time, on the control issue's reference plant:
// az 1.5°/s, el 1.0°/s, τ 0.3 s, backlash 0.05°, stiction 0.1.
#include "azt/sim/station_sim.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/sim/reference_station.hpp"

namespace azt::sim {
namespace {

/// The reference station, starting where the synthetic targets below begin.
StationSimSetup reference(int bits, double window_deg) {
  StationSimSetup s = reference_station(bits, window_deg);
  s.plant.az.start_deg = 100.0;
  s.plant.el.start_deg = 20.0;
  return s;
}

/// A target moving like the Moon across the southern sky: 15°/h in azimuth, 5°/h in elevation.
SkyTrack moon_like() {
  return [](double t_s) {
    return std::optional<control::AzEl>(
        control::AzEl{120.0 + t_s * 15.0 / 3600.0, 25.0 + t_s * 5.0 / 3600.0});
  };
}

class Tracking : public ::testing::TestWithParam<std::tuple<int, double>> {};

TEST_P(Tracking, StaysWithinTheWindowPlusTwoLsbAndStartsRarely) {
  const auto [bits, window] = GetParam();
  const StationSimSetup setup = reference(bits, window);
  const SimResult r = simulate_tracking(setup, moon_like(), 3600.0);
  const double lsb = 360.0 / std::ldexp(1.0, bits);
  ASSERT_TRUE(r.acquired_s.has_value());
  EXPECT_TRUE(r.faults.empty()) << r.faults.front();
  EXPECT_LE(r.max_error_deg, window + 2.0 * lsb) << "bits " << bits << " window " << window;
  // The seed's algorithm restarts every L2 of travel (a few more for the acquisition and for
  // counts that flicker at the stop). Leading the target by the window swings the error across
  // 2·window + 1 LSB per start: half the starts when the window is large against the LSB.
  const double l2 = window + lsb;
  EXPECT_LE(static_cast<double>(r.az.starts), r.az.travel_deg / l2 + 5.0);
  EXPECT_LE(static_cast<double>(r.el.starts), r.el.travel_deg / l2 + 5.0);
  if (window > 0.0) {
    const double swing = 2.0 * window + lsb;
    EXPECT_LE(static_cast<double>(r.az.starts), 1.1 * r.az.travel_deg / swing + 2.0);
    EXPECT_LE(static_cast<double>(r.el.starts), 1.1 * r.el.travel_deg / swing + 2.0);
  }
  EXPECT_EQ(r.hub.frames_ok(),
            static_cast<std::uint32_t>(std::llround(3600.0 / setup.station.tick_s)));
}

INSTANTIATE_TEST_SUITE_P(BitsAndWindows, Tracking,
                         ::testing::Combine(::testing::Values(12, 16),
                                            ::testing::Values(0.0, 0.1, 0.5)));

TEST(Slew, HalfTurnInAzimuthNearTheMinimumTimeWithoutOvershoot) {
  for (int bits : {12, 16}) {
    const StationSimSetup setup = reference(bits, 0.0);
    const SimResult r = simulate_slew(setup, control::AzEl{280.0, 20.0}, 600.0);
    const double lsb = 360.0 / std::ldexp(1.0, bits);
    ASSERT_TRUE(r.slew_time_s.has_value());
    EXPECT_NEAR(r.slew_min_time_s, 180.0 / 1.5, 1e-9);
    EXPECT_LE(*r.slew_time_s, 1.10 * r.slew_min_time_s + setup.station.az_control.ramp_s) << bits;
    EXPECT_LE(r.az.overshoot_deg, lsb) << bits;
    EXPECT_LE(r.max_error_deg, 2.0 * lsb) << bits;
    EXPECT_TRUE(r.faults.empty());
  }
}

TEST(Slew, OverlapRotatorGoesThroughNorthTheShortWay) {
  StationSimSetup setup = reference(12, 0.0);
  setup.station.az_range = control::AzimuthRange{0.0, 450.0};
  setup.plant.az.max_deg = 450.0;
  setup.plant.az.start_deg = 350.0;
  const SimResult r = simulate_slew(setup, control::AzEl{20.0, 20.0}, 600.0);
  ASSERT_TRUE(r.slew_time_s.has_value());
  EXPECT_LT(*r.slew_time_s, 30.0);  // 30° the short way, not 330° back
}

TEST(Faults, CorruptLinkWithCrcStillTracks) {
  StationSimSetup setup = reference(12, 0.1);
  setup.plant.link.byte_corruption = 0.05;
  setup.plant.link.frame_loss = 0.05;
  const SimResult r = simulate_tracking(setup, moon_like(), 1800.0);
  EXPECT_TRUE(r.faults.empty()) << r.faults.front();
  EXPECT_LE(r.max_error_deg, 0.1 + 2.0 * 360.0 / 4096.0);
  EXPECT_GT(r.hub.rejected(), 0u);
}

TEST(Faults, LostLinkStopsTheMotorsWithoutLatching) {
  StationSimSetup setup = reference(12, 0.0);
  setup.plant.link.frame_loss = 1.0;
  const SimResult r = simulate_slew(setup, control::AzEl{280.0, 60.0}, 20.0);
  EXPECT_GT(r.max_error_deg, 100.0);  // never moved
  EXPECT_TRUE(r.faults.empty());
}

}  // namespace
}  // namespace azt::sim

namespace azt::sim {
namespace {

SimResult slew_with_fault(AxisFaultKind kind, bool azimuth, std::int32_t counts = 0) {
  StationSimSetup setup = reference(12, 0.0);
  setup.plant.faults.push_back(ScheduledFault{5.0, azimuth, AxisFault{kind, counts}});
  return simulate_slew(setup, control::AzEl{280.0, 60.0}, 200.0);
}

bool has_fault(const SimResult& r, const std::string& what) {
  for (const auto& f : r.faults) {
    if (f.find(what) != std::string::npos) return true;
  }
  return false;
}

TEST(Faults, FrozenShaftLatchesAStallAndStopsTheMotor) {
  const SimResult r = slew_with_fault(AxisFaultKind::FrozenShaft, true);
  EXPECT_TRUE(has_fault(r, "az: stall")) << (r.faults.empty() ? "" : r.faults.front());
  EXPECT_EQ(r.max_duty_after_fault, 0.0);
  EXPECT_GT(r.az.max_error_deg, 100.0);  // stopped where it froze, never "arrived"
}

TEST(Faults, ReversedMotorLatchesARunaway) {
  const SimResult r = slew_with_fault(AxisFaultKind::ReversedMotor, false);
  EXPECT_TRUE(has_fault(r, "el: runaway")) << (r.faults.empty() ? "" : r.faults.front());
  EXPECT_EQ(r.max_duty_after_fault, 0.0);
}

TEST(Faults, SlippedEncoderLatchesAJump) {
  const SimResult r = slew_with_fault(AxisFaultKind::EncoderOffset, true, 1000);  // 88°
  EXPECT_TRUE(has_fault(r, "az: encoder_jump")) << (r.faults.empty() ? "" : r.faults.front());
  EXPECT_EQ(r.max_duty_after_fault, 0.0);
}

TEST(Faults, OneGlitchIsIgnored) {
  const SimResult r = slew_with_fault(AxisFaultKind::EncoderGlitch, true, 1000);
  EXPECT_TRUE(r.faults.empty()) << r.faults.front();
  ASSERT_TRUE(r.slew_time_s.has_value());
  EXPECT_LE(r.max_error_deg, 2.0 * 360.0 / 4096.0);
}

}  // namespace
}  // namespace azt::sim

namespace azt::sim {
namespace {

/// Sets at t = 600 s: elevation 5° falling 0.5°/min.
SkyTrack setting() {
  return [](double t_s) {
    return std::optional<control::AzEl>(control::AzEl{250.0, 5.0 - t_s / 120.0});
  };
}

TEST(OutOfRange, HoldsWhereTheTargetSet) {
  StationSimSetup setup = reference(12, 0.1);
  setup.plant.az.start_deg = 250.0;
  setup.plant.el.start_deg = 5.0;
  const SimResult r = simulate_tracking(setup, setting(), 1200.0);
  EXPECT_TRUE(r.faults.empty());
  // Errors count only while the target was up: none beyond the window + 2 LSB.
  EXPECT_LE(r.max_error_deg, 0.1 + 2.0 * 360.0 / 4096.0);
  EXPECT_NEAR(r.final_position.az_deg, 250.0, 0.2);  // held, not parked
  EXPECT_GT(r.final_position.el_deg, -0.5);
}

TEST(OutOfRange, ParksWhenConfigured) {
  StationSimSetup setup = reference(12, 0.1);
  setup.plant.az.start_deg = 250.0;
  setup.plant.el.start_deg = 5.0;
  setup.station.park_when_out_of_range = control::AzEl{180.0, 0.0};
  const SimResult r = simulate_tracking(setup, setting(), 1200.0);
  EXPECT_TRUE(r.faults.empty());
  // 70° of azimuth at 1.5°/s after the set at 600 s: parked well before 1200 s. The slew to park
  // is not tracking error.
  EXPECT_LE(r.max_error_deg, 0.1 + 2.0 * 360.0 / 4096.0);
  // Parked like any fixed target: within the window + 2 LSB.
  EXPECT_NEAR(r.final_position.az_deg, 180.0, 0.1 + 2.0 * 360.0 / 4096.0);
  EXPECT_NEAR(r.final_position.el_deg, 0.0, 0.1 + 2.0 * 360.0 / 4096.0);
}

}  // namespace
}  // namespace azt::sim
