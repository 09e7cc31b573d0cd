// The reduction chain on worked examples from outside programs, and properties that must hold for
// any instant and station. The wide randomized comparison with swetest and astropy lives in
// tests/conformance/.
#include "azt/astro/sky.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/target.hpp"

namespace azt::astro {
namespace {

constexpr double kArcsecDeg = 1.0 / 3600.0;

TimeScales at(int y, int mo, int d, int h, int mi, double s, double dut1_s) {
  auto utc = UtcInstant::from_calendar(y, mo, d, h, mi, s);
  EXPECT_TRUE(utc.ok());
  auto t = make_time_scales(*utc, dut1_s, LeapSecondTable::builtin());
  EXPECT_TRUE(t.ok());
  return *t;
}

struct Fixture {
  ErfaEphemeris eph;
  Epoch epoch;
  Station station;
  Fixture(const TimeScales& t, const Observer& o)
      : epoch(*make_epoch(eph, t)), station(make_station(epoch, o)) {}
};

// ../shared/oracles/README.md §2: an independent ERFA chain (eraApco13, IAU 2006/2000A) at
// 2025-03-14 06:00:00 UTC, 46.189 N 79.393 W 300 m, UT1 = UTC + 0.203387 s.
TEST(SkyErfa, MatchesTheOracleNotesErfaChain) {
  Fixture f(at(2025, 3, 14, 6, 0, 0.0, 69.184 - 68.980613), Observer{46.189, -79.393, 300.0});
  const Place sun = observe_sun(f.epoch, f.station);
  EXPECT_NEAR(sun.az_deg, 11.9272338, 0.02 * kArcsecDeg);
  EXPECT_NEAR(sun.el_geometric_deg, -45.6342790, 0.02 * kArcsecDeg);
  EXPECT_NEAR(*sun.range_rate_km_s, 0.421368, 2e-6);
  const Place moon = *observe_moon(f.eph, f.epoch, f.station);
  EXPECT_NEAR(moon.az_deg, 192.3769552, 0.02 * kArcsecDeg);
  EXPECT_NEAR(moon.el_geometric_deg, 45.4544030, 0.02 * kArcsecDeg);
  EXPECT_NEAR(*moon.distance_km, 396837.911, 0.005);
  EXPECT_NEAR(*moon.range_rate_km_s, 0.078280, 2e-6);
}

// ../shared/reference/astronomy-and-eme.md §4 sample vectors (eraMoon98, UT1 = UTC, computed
// without light time: agreement expected within ~20″ and ~0.2 m/s ≈ 14 Hz at 10 GHz). Their range
// is the geometric |M(t) − O(t)|; ours is the barycentric light-time range, which differs by
// τ·u·V_earth ≤ 1.3 s × 30 km/s ≈ 41 km (../shared/oracles/README.md, Pitfalls).
// Station A 50 N 10 E, B 42 N 72 W, both h = 0; f = 10368 MHz; 2025-06-01.
TEST(SkyErfa, EmeSampleVectors) {
  struct Row {
    int hour;
    double az, el, range_km, rate_m_s, self_khz, dx_khz, delay_s;
  };
  const Row rows[] = {{9, 64.83, 0.92, 385904.7, -187.86, 12.994, 1.916, 2.5745},
                      {12, 98.17, 27.85, 383771.3, -180.83, 12.507, 9.698, 2.5602},
                      {15, 145.26, 51.30, 382519.9, -31.98, 2.212, 9.429, 2.5519},
                      {18, 215.28, 50.44, 383301.6, 176.92, -12.237, 1.185, 2.5571},
                      {21, 260.93, 25.92, 386126.8, 327.44, -22.648, -10.527, 2.5760}};
  for (const Row& r : rows) {
    const TimeScales t = at(2025, 6, 1, r.hour, 0, 0.0, 0.0);
    Fixture a(t, Observer{50.0, 10.0, 0.0});
    const Station b = make_station(a.epoch, Observer{42.0, -72.0, 0.0});
    const Place ma = *observe_moon(a.eph, a.epoch, a.station);
    const Place mb = *observe_moon(a.eph, a.epoch, b);
    EXPECT_NEAR(ma.az_deg, r.az, 0.006 + 20 * kArcsecDeg) << r.hour;
    EXPECT_NEAR(ma.el_geometric_deg, r.el, 0.006 + 20 * kArcsecDeg) << r.hour;
    EXPECT_NEAR(*ma.distance_km, r.range_km, 41.0) << r.hour;
    EXPECT_NEAR(*ma.range_rate_km_s * 1000.0, r.rate_m_s, 0.2) << r.hour;
    EXPECT_NEAR(self_echo_doppler_hz(10368.0, *ma.range_rate_km_s) / 1000.0, r.self_khz, 0.015);
    EXPECT_NEAR(dx_echo_doppler_hz(10368.0, *ma.range_rate_km_s, *mb.range_rate_km_s) / 1000.0,
                r.dx_khz, 0.015);
    // 41 km of range convention (0.27 ms) plus the table's rounding to 0.1 ms.
    EXPECT_NEAR(echo_delay_s(*ma.distance_km), r.delay_s, 0.00033);
  }
}

// ../shared/reference/astronomy-and-eme.md Appendix A: eraAtco13, 2025-06-01 00:00 UTC,
// 50 N 10 E, airless (values rounded to 1e-4°).
TEST(SkyIcrs, RadioSourcesAsEraAtco13) {
  Fixture f(at(2025, 6, 1, 0, 0, 0.0, 0.0), Observer{50.0, 10.0, 0.0});
  struct Row {
    const char* key;
    double az, el;
  };
  for (const Row& r : {Row{"casa", 42.6210, 40.4041}, Row{"cyga", 92.5549, 60.6128},
                       Row{"vira", 263.9316, 21.0856}, Row{"sgra", 173.6889, 10.7304}}) {
    const Target t = *parse_target(r.key);
    const Place p = observe_icrs(f.epoch, f.station, t.ra_deg, t.dec_deg);
    EXPECT_NEAR(p.az_deg, r.az, 0.0001) << r.key;
    EXPECT_NEAR(p.el_geometric_deg, r.el, 0.0001) << r.key;
    EXPECT_FALSE(p.distance_km.has_value());
  }
  // Same source: "radio refraction at 1013 hPa, 10 °C, 50 % adds 0.0205° to Cas A" — a difference
  // of two elevations rounded to 1e-4°, hence the tolerance.
  const Atmosphere radio{1013.0, 10.0, 0.5, RefractionModel::Radio};
  const Observation cas = *observe(*parse_target("casa"), f.eph, f.epoch, f.station, radio);
  EXPECT_NEAR(cas.el_deg - cas.place.el_geometric_deg, 0.0205, 0.0001);
}

TEST(SkyProperties, RangeRateIsTheDerivativeOfRange) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> day(0.0, 20000.0), lat(-70.0, 70.0), lon(-180.0, 180.0);
  ErfaEphemeris eph;
  for (int i = 0; i < 40; ++i) {
    const double mjd = 45000.0 + day(rng);
    const Observer o{lat(rng), lon(rng), 500.0};
    auto distance = [&](double dt_s) {
      UtcInstant u;
      u.jd = {2400000.5 + std::floor(mjd), mjd - std::floor(mjd) + dt_s / 86400.0};
      const Epoch e = *make_epoch(eph, *make_time_scales(u, 0.0, LeapSecondTable::builtin()));
      const Station s = make_station(e, o);
      return std::make_pair(*observe_moon(eph, e, s), observe_sun(e, s));
    };
    const auto [moon0, sun0] = distance(0.0);
    const auto [moon_p, sun_p] = distance(0.5);
    const auto [moon_m, sun_m] = distance(-0.5);
    // Central difference over 1 s: truncation error < 1e-6 km/s for both bodies. The Sun's
    // differs by up to 3.8e-7 km/s on x86-64 and 2.1e-6 on arm64 (ERFA built there with fused
    // multiply-adds): 5e-6 km/s, 0.2 Hz of Doppler at 10 GHz, holds on both.
    EXPECT_NEAR(*moon0.range_rate_km_s, *moon_p.distance_km - *moon_m.distance_km, 2e-6) << i;
    EXPECT_NEAR(*sun0.range_rate_km_s, *sun_p.distance_km - *sun_m.distance_km, 5e-6) << i;
    EXPECT_GE(moon0.az_deg, 0.0);
    EXPECT_LT(moon0.az_deg, 360.0);
    EXPECT_LE(std::abs(moon0.el_geometric_deg), 90.0);
    EXPECT_GT(*moon0.distance_km, 350000.0);
    EXPECT_LT(*moon0.distance_km, 410000.0);
  }
}

TEST(SkyProperties, NorthPoleSeesPolarisNearTheZenithAndTheEquatorSeesItOnTheHorizon) {
  // Polaris, ICRS 02h31m49.09s +89°15′50.8″ (Hipparcos): elevation ≈ latitude within 1°.
  Fixture f(at(2024, 1, 1, 0, 0, 0.0, 0.0), Observer{89.9, 0.0, 0.0});
  const double ra = 15.0 * (2.0 + 31.0 / 60.0 + 49.09 / 3600.0);
  const double dec = 89.0 + 15.0 / 60.0 + 50.8 / 3600.0;
  EXPECT_NEAR(observe_icrs(f.epoch, f.station, ra, dec).el_geometric_deg, 89.9, 1.0);
  const Station equator = make_station(f.epoch, Observer{0.0, 0.0, 0.0});
  const Place p = observe_icrs(f.epoch, equator, ra, dec);
  EXPECT_NEAR(p.el_geometric_deg, 0.0, 1.0);
  EXPECT_NEAR(std::fmod(p.az_deg + 180.0, 360.0), 180.0, 1.0);  // due north
}

TEST(Doppler, SignsAndDefinitions) {
  // Receding Moon (ṙ > 0) lowers the echo frequency.
  EXPECT_LT(self_echo_doppler_hz(1296.0, 0.1), 0.0);
  // −2·f·ṙ/c: 1 km/s at 10368 MHz = −2·10368e6/299792.458 = −69167.85 Hz.
  EXPECT_NEAR(self_echo_doppler_hz(10368.0, 1.0), -69167.85, 0.01);
  // DX Doppler with both stations the same equals the self echo.
  EXPECT_DOUBLE_EQ(dx_echo_doppler_hz(432.0, 0.2, 0.2), self_echo_doppler_hz(432.0, 0.2));
  // 384400 km (mean distance) → 2·384400/299792.458 = 2.564441 s round trip.
  EXPECT_NEAR(echo_delay_s(384400.0), 2.564441, 1e-6);
}

TEST(Observe, RefractionRaisesTargetsAboveTheHorizon) {
  Fixture f(at(2025, 3, 14, 6, 0, 0.0, 0.0), Observer{46.189, -79.393, 300.0});
  const Atmosphere none{1013.25, 10.0, 0.5, RefractionModel::None};
  const Atmosphere radio{1013.25, 10.0, 0.5, RefractionModel::Radio};
  const Observation a = *observe(Target::moon(), f.eph, f.epoch, f.station, none);
  const Observation b = *observe(Target::moon(), f.eph, f.epoch, f.station, radio);
  EXPECT_EQ(a.el_deg, a.place.el_geometric_deg);
  EXPECT_GT(b.el_deg, b.place.el_geometric_deg);
  EXPECT_EQ(a.place.az_deg, b.place.az_deg);
}

}  // namespace
}  // namespace azt::astro
