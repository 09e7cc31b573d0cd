// The control issue's table: the reference plant (az 1.5°/s, el 1.0°/s, τ 0.3 s, backlash 0.05°,
// stiction 0.1) tracking the Moon for 6 h from FN06HE, for 9-, 12-, 14- and 16-bit encoders and
// windows of 0, 0.1 and 0.5°, plus a 180° azimuth slew. Prints a Markdown table.
// Run: build/bench/azt_tracking_table [START_ISO8601Z]   (not a test: see tests/unit for bars)
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/target.hpp"
#include "azt/proto/hub_frame.hpp"
#include "azt/sim/reference_station.hpp"
#include "azt/sim/sky_track.hpp"
#include "azt/sim/station_sim.hpp"
#ifdef AZT_HAVE_SWISS
#include "azt/astro/swiss_ephemeris.hpp"
#endif

namespace {

using azt::sim::StationSimSetup;

constexpr double kHours = 6.0;

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

int main(int argc, char** argv) {
  const std::string start_text = argc > 1 ? argv[1] : "2025-03-14T00:00:00Z";
  auto start = azt::astro::parse_iso8601_utc(start_text);
  if (!start) {
    std::fprintf(stderr, "%s\n", start.error().message.c_str());
    return 2;
  }
#ifdef AZT_HAVE_SWISS
  auto swiss = azt::astro::SwissEphemeris::open();
  const azt::astro::ErfaEphemeris erfa;
  const azt::astro::Ephemeris& eph =
      swiss ? static_cast<const azt::astro::Ephemeris&>(*swiss) : erfa;
#else
  const azt::astro::ErfaEphemeris eph;
#endif
  azt::sim::SkyTrackSetup track;
  track.ephemeris = &eph;
  track.target = azt::astro::Target::moon();
  track.observer = azt::astro::Observer{46.189, -79.393, 300.0};
  track.start = *start;
  track.leap_table = &azt::astro::LeapSecondTable::builtin();
  std::printf("Moon from FN06HE, %s + %.0f h, ephemeris %s\n\n", start_text.c_str(), kHours,
              eph.name().c_str());
  std::printf(
      "| bits | window ° | max error ° | bound (w+2 LSB) ° | rms ° | starts/h az | el | "
      "seed starts/h az (travel/L2) | el | 180° slew s (min 120) | overshoot ° | CPU s per sim h "
      "|\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int bits : {9, 12, 14, 16}) {
    for (double window : {0.0, 0.1, 0.5}) {
      const StationSimSetup setup = azt::sim::reference_station(bits, window);
      const double t0 = cpu_seconds();
      const auto r =
          azt::sim::simulate_tracking(setup, azt::sim::make_sky_track(track), kHours * 3600.0);
      const double cpu_per_hour = (cpu_seconds() - t0) / kHours;
      const double lsb = azt::proto::hub_resolution_deg(static_cast<std::uint8_t>(bits));
      const double l2 = window + lsb;
      const double hours = kHours - r.acquired_s.value_or(0.0) / 3600.0;
      StationSimSetup slew_setup = azt::sim::reference_station(bits, window);
      slew_setup.plant.az.start_deg = 90.0;
      const auto slew = azt::sim::simulate_slew(slew_setup, azt::control::AzEl{270.0, 10.0}, 600.0);
      std::printf(
          "| %d | %.1f | %.4f | %.4f | %.4f | %.1f | %.1f | %.1f | %.1f | %.2f | %.4f | %.3f |%s\n",
          bits, window, r.max_error_deg, window + 2 * lsb, r.rms_error_deg, r.az.starts_per_hour,
          r.el.starts_per_hour, r.az.travel_deg / l2 / hours, r.el.travel_deg / l2 / hours,
          slew.slew_time_s.value_or(-1.0), std::max(slew.az.overshoot_deg, slew.el.overshoot_deg),
          cpu_per_hour, r.faults.empty() ? "" : (" faults: " + r.faults.front()).c_str());
    }
  }
  return 0;
}
