#include "common/sky_setup.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/maidenhead.hpp"
#include "common/usage_error.hpp"
#ifdef AZT_HAVE_SWISS
#include "azt/astro/swiss_ephemeris.hpp"
#endif

namespace azt::app {
namespace {

// Debian's tzdata installs the IERS/NIST list here (IETF format).
constexpr const char* kTzdataLeapList = "/usr/share/zoneinfo/leap-seconds.list";

astro::LeapSecondTable load_leap_table() {
  std::ifstream in(kTzdataLeapList);
  if (!in) {
    spdlog::warn("{} not readable; using the built-in leap-second table", kTzdataLeapList);
    return astro::LeapSecondTable::builtin();
  }
  std::stringstream text;
  text << in.rdbuf();
  auto parsed = astro::LeapSecondTable::parse_ietf_list(text.str());
  if (!parsed) {
    spdlog::warn("{}: {}; using the built-in leap-second table", kTzdataLeapList,
                 parsed.error().message);
    return astro::LeapSecondTable::builtin();
  }
  // Prefer whichever table is valid for longer: a stale tzdata must not override a newer build.
  if (parsed->expiry_mjd() < astro::LeapSecondTable::builtin().expiry_mjd()) {
    return astro::LeapSecondTable::builtin();
  }
  return std::move(parsed).value();
}

}  // namespace

astro::Observer observer_from_grid(const std::string& grid, double height_m) {
  auto square = astro::decode_locator(grid);
  if (!square) throw UsageError("--grid: " + square.error().message);
  return observer_from_coordinates(square->lat_deg, square->lon_deg, height_m);
}

astro::Observer observer_from_coordinates(double lat_deg, double lon_deg, double height_m) {
  auto observer = astro::Observer::make(lat_deg, lon_deg, height_m);
  if (!observer) throw UsageError(observer.error().message);
  return *observer;
}

std::string grid_of(const astro::Observer& observer) {
  auto grid = astro::encode_locator(observer.lat_deg, observer.lon_deg, 6);
  return grid ? *grid : std::string("?");
}

void check_dut1(double dut1_s) {
  if (!std::isfinite(dut1_s) || std::fabs(dut1_s) > astro::kDut1HardLimitS) {
    throw UsageError("--dut1 must be within ±10 s (IERS keeps |UT1−UTC| < 0.9 s)");
  }
  if (std::fabs(dut1_s) > astro::kDut1NominalLimitS) {
    spdlog::warn("DUT1 = {} s is beyond the ±0.9 s that IERS maintains; accepted", dut1_s);
  }
}

std::unique_ptr<astro::Ephemeris> open_ephemeris(const std::string& choice) {
  if (choice == "erfa") return std::make_unique<astro::ErfaEphemeris>();
  if (choice != "swiss" && choice != "auto") {
    throw UsageError("unknown ephemeris '" + choice + "' (use auto, erfa or swiss)");
  }
#ifdef AZT_HAVE_SWISS
  auto swiss = astro::SwissEphemeris::open();
  if (swiss) return std::make_unique<astro::SwissEphemeris>(std::move(swiss).value());
  if (choice == "swiss") throw UsageError(swiss.error().message);
  spdlog::info("{}; using ERFA", swiss.error().message);
#else
  if (choice == "swiss") {
    throw UsageError("this azeltrack was built without Swiss Ephemeris (libswe-dev)");
  }
#endif
  return std::make_unique<astro::ErfaEphemeris>();
}

const astro::LeapSecondTable& leap_table() {
  static const astro::LeapSecondTable table = load_leap_table();
  return table;
}

astro::UtcInstant utc_now() {
  const auto since_epoch = std::chrono::system_clock::now().time_since_epoch();
  return astro::UtcInstant::from_unix_seconds(std::chrono::duration<double>(since_epoch).count());
}

Result<astro::TimeScales> time_scales_for(const astro::UtcInstant& utc, double dut1_s) {
  auto time = astro::make_time_scales(utc, dut1_s, leap_table());
  if (!time) return time.error();
  static bool warned = false;
  if (time->leap_table_expired && !warned) {
    warned = true;
    spdlog::warn(
        "the leap-second table expired before this instant: TAI−UTC = {} s is assumed; "
        "update tzdata if a leap second has been announced since",
        time->tai_minus_utc_s);
  }
  return time;
}

astro::TimeScales time_scales_at(const astro::UtcInstant& utc, double dut1_s) {
  auto time = time_scales_for(utc, dut1_s);
  if (!time) throw UsageError(time.error().message);
  return *time;
}

astro::Observer observer_from_options(const std::string& grid, const std::string& lat,
                                      const std::string& lon, const std::string& alt,
                                      std::string& grid_out) {
  const double alt_m = parse_number_option("--alt", alt);
  if (!grid.empty()) {
    if (!lat.empty() || !lon.empty())
      throw UsageError("give either --grid or --lat/--lon, not both");
    grid_out = grid;
    return observer_from_grid(grid, alt_m);
  }
  if (lat.empty() || lon.empty()) {
    throw UsageError("the station is needed: --lat and --lon, or --grid");
  }
  const astro::Observer o = observer_from_coordinates(parse_number_option("--lat", lat),
                                                      parse_number_option("--lon", lon), alt_m);
  grid_out = grid_of(o);
  return o;
}

}  // namespace azt::app
