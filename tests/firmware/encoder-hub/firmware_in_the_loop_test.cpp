// End to end (docs/encoder-hub.md): the Moon tracked for one simulated hour by the daemon's
// station, reading the plants through the EncoderHub firmware on a simulated ATmega328P, against
// the same hour read through the plain hub model. The firmware's frames come 50 times a second,
// each up to a frame period old: the tracking must stay within the plain simulation's error + 1
// LSB.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ctime>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/tabulated_ephemeris.hpp"
#include "azt/avr/firmware_hub.hpp"
#include "azt/sim/reference_station.hpp"
#include "azt/sim/sky_track.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::avr {
namespace {

/// The Moon from FN06HE on the night of 2025-03-14 (moon_tracking_test's), ERFA through a table.
sim::SkyTrack moon() {
  static const astro::UtcInstant start = *astro::UtcInstant::from_calendar(2025, 3, 14, 0, 0, 0.0);
  static const astro::ErfaEphemeris erfa;
  static const astro::TabulatedEphemeris table = *astro::TabulatedEphemeris::build(
      erfa, astro::make_time_scales(start, 0.0, astro::LeapSecondTable::builtin())->tt, 0.1);
  sim::SkyTrackSetup track;
  track.ephemeris = &table;
  track.target = astro::Target::moon();
  track.observer = astro::Observer{46.189, -79.393, 300.0};
  track.start = start;
  track.leap_table = &astro::LeapSecondTable::builtin();
  return sim::make_sky_track(track);
}

void print(const char* name, const sim::SimResult& r, double cpu_s) {
  std::printf(
      "[ measure  ] %s: max error %.4f deg (az %.4f, el %.4f), rms %.4f deg, starts az %llu el "
      "%llu, frames %llu (rejected %llu), %.1f s of CPU\n",
      name, r.max_error_deg, r.az.max_error_deg, r.el.max_error_deg, r.rms_error_deg,
      static_cast<unsigned long long>(r.az.starts), static_cast<unsigned long long>(r.el.starts),
      static_cast<unsigned long long>(r.hub.frames_ok()),
      static_cast<unsigned long long>(r.hub.rejected()), cpu_s);
}

double cpu_s_since(std::clock_t start) {
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

TEST(FirmwareInTheLoop, TheMoonForAnHourWithinThePlainSimulationsErrorPlusOneLsb) {
  constexpr int kBits = 12;  // AS5045-class encoders on both axes
  constexpr double kWindowDeg = 0.1;
  constexpr double kSeconds = 3600.0;
  const double lsb = 360.0 / std::ldexp(1.0, kBits);
  const sim::StationSimSetup setup = sim::reference_station(kBits, kWindowDeg);

  std::clock_t start = std::clock();
  const sim::SimResult plain = sim::simulate_tracking(setup, moon(), kSeconds);
  print("plain model", plain, cpu_s_since(start));

  auto hub = FirmwareHub::load(setup.plant, AZT_HUB_ELF);
  ASSERT_TRUE(hub.ok()) << hub.error().message;
  start = std::clock();
  const sim::SimResult r = sim::simulate_tracking(setup, moon(), kSeconds, std::move(hub).value());
  print("hub firmware", r, cpu_s_since(start));

  ASSERT_TRUE(plain.acquired_s.has_value());
  ASSERT_TRUE(r.acquired_s.has_value());
  EXPECT_TRUE(r.faults.empty()) << r.faults.front();
  EXPECT_GT(r.az.travel_deg, 5.0);  // the Moon really moved
  EXPECT_LE(r.az.max_error_deg, plain.az.max_error_deg + lsb);
  EXPECT_LE(r.el.max_error_deg, plain.el.max_error_deg + lsb);
  EXPECT_LE(r.max_error_deg, kWindowDeg + 2.0 * lsb);  // the reference target, as plain meets it
  // 50 frames a second for the hour, none refused by the decoder.
  EXPECT_GE(r.hub.frames_ok(), static_cast<std::uint64_t>(49.9 * kSeconds));
  EXPECT_EQ(r.hub.rejected(), 0U);
}

}  // namespace
}  // namespace azt::avr
