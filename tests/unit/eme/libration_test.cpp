// The Moon's apparent libration and WSJT-X's echo width (docs/eme.md): the sub-observer point
// swings within the libration's known bounds over a month, the formula's constants, and the
// width of a real Moon at the bands in the range operators see.
#include "azt/eme/libration.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/time_scales.hpp"

namespace azt::eme {
namespace {

struct Seen {
  astro::Place moon;
  double tt_jd = 0.0;
};

Seen moon_at(double unix_s, const astro::Observer& where) {
  static const astro::ErfaEphemeris eph;
  const auto t = astro::make_time_scales(astro::UtcInstant::from_unix_seconds(unix_s), 0.0,
                                         astro::LeapSecondTable::builtin());
  const auto epoch = astro::make_epoch(eph, *t);
  const auto moon = astro::observe_moon(eph, *epoch, astro::make_station(*epoch, where));
  return {*moon, t->tt.total()};
}

constexpr double kMarch2025 = 1740787200.0;  // 2025-03-01 00:00 UTC
const astro::Observer kFn06{46.19, -79.39, 300.0};

TEST(Libration, StaysWithinTheKnownSwingsOverAMonth) {
  // Optical libration reaches about ±7.9° in longitude and ±6.9° in latitude, plus about 1° of
  // diurnal libration for an observer on the surface.
  double max_lon = 0.0;
  double max_lat = 0.0;
  for (int hour = 0; hour < 24 * 30; hour += 6) {
    const Seen s = moon_at(kMarch2025 + hour * 3600.0, kFn06);
    const Libration l = apparent_libration(s.moon, s.tt_jd);
    max_lon = std::fmax(max_lon, std::fabs(l.lon_deg));
    max_lat = std::fmax(max_lat, std::fabs(l.lat_deg));
  }
  EXPECT_GT(max_lon, 4.5);
  EXPECT_LT(max_lon, 9.5);
  EXPECT_GT(max_lat, 5.0);
  EXPECT_LT(max_lat, 8.5);
}

TEST(EchoWidth, WsjtxsFormula) {
  const Libration a{1.0, 2.0};
  const Libration b{1.001, 2.0};
  // 0.5 · 6741 · 1.296 GHz · 2 · 0.001 °/min
  EXPECT_NEAR(self_echo_width_hz(a, b, 1296.0), 0.5 * 6741.0 * 1.296 * 2.0 * 0.001, 1e-9);
  EXPECT_NEAR(self_echo_width_hz(a, Libration{1.0, 2.001}, 1296.0),
              self_echo_width_hz(a, b, 1296.0), 1e-9)
      << "latitude counts the same";
  // Across ±180° of longitude the change is small, not a turn.
  EXPECT_NEAR(self_echo_width_hz({179.9995, 0.0}, {-179.9995, 0.0}, 1000.0),
              0.5 * 6741.0 * 2.0 * 0.001, 1e-6);
  // DX: the two stations' changes add; equal ones give the self-echo width.
  EXPECT_NEAR(dx_echo_width_hz(a, b, a, b, 1296.0), self_echo_width_hz(a, b, 1296.0), 1e-9);
  EXPECT_NEAR(dx_echo_width_hz(a, b, b, a, 1296.0), 0.0, 1e-9) << "opposite changes cancel";
}

TEST(EchoWidth, ARealMoonSpreadsItsEchoByHertzToTensOfHertz) {
  const Seen now = moon_at(kMarch2025 + 6 * 3600.0, kFn06);
  const Seen later = moon_at(kMarch2025 + 6 * 3600.0 + 60.0, kFn06);
  const double w = self_echo_width_hz(apparent_libration(now.moon, now.tt_jd),
                                      apparent_libration(later.moon, later.tt_jd), 1296.0);
  // The libration moves the sub-observer point by about a degree a day, 0.0005–0.003° a minute.
  EXPECT_GT(w, 1.0);
  EXPECT_LT(w, 40.0);
}

}  // namespace
}  // namespace azt::eme
