#pragma once

#include <memory>
#include <optional>
#include <string>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/refraction.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

/// Where the station is, how the sky is computed, and for which frequency: what `sky` takes
/// from its options and `watch` from the configuration file.
struct SkySettings {
  astro::Observer observer;
  std::string grid;                   ///< the station's locator (given or derived)
  std::optional<astro::Observer> dx;  ///< a DX station for DX echo Doppler
  std::string dx_grid;
  double dut1_s = 0.0;
  std::string ephemeris = "auto";  ///< auto | erfa | swiss
  astro::Atmosphere atmosphere;
  std::optional<double> freq_mhz;
};

/// Observer from a locator (its square's centre, at `height_m`). Throws UsageError.
astro::Observer observer_from_grid(const std::string& grid, double height_m);
/// Observer from coordinates. Throws UsageError naming the bad value.
astro::Observer observer_from_coordinates(double lat_deg, double lon_deg, double height_m);
/// The station from the command line: `grid`, or `lat` and `lon` (texts as typed), at `alt`
/// metres. Throws UsageError for both, neither, or a bad number. `grid_out` gets its locator.
astro::Observer observer_from_options(const std::string& grid, const std::string& lat,
                                      const std::string& lon, const std::string& alt,
                                      std::string& grid_out);
/// The station's own locator, 6 characters, for display.
std::string grid_of(const astro::Observer& observer);
/// Checks DUT1: throws UsageError beyond ±10 s, warns beyond ±0.9 s.
void check_dut1(double dut1_s);

/// The ephemeris asked for: "swiss" (error if unavailable), "erfa", or "auto" (Swiss Ephemeris
/// when built in and its data files are present, else ERFA, with a note in the log).
std::unique_ptr<astro::Ephemeris> open_ephemeris(const std::string& choice);

/// The leap-second table: tzdata's leap-seconds.list when readable and valid, else the built-in
/// one (with a warning). Loaded once per process.
const astro::LeapSecondTable& leap_table();

/// UTC now from the system clock.
astro::UtcInstant utc_now();

/// Time scales for `utc`, warning once when the leap-second table has expired; an error outside
/// the table's span.
Result<astro::TimeScales> time_scales_for(const astro::UtcInstant& utc, double dut1_s);
/// The same for the command line: throws UsageError.
astro::TimeScales time_scales_at(const astro::UtcInstant& utc, double dut1_s);

}  // namespace azt::app
