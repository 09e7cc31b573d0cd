#include "azt/astro/tabulated_ephemeris.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/sky.hpp"

namespace azt::astro {
namespace {

constexpr double kMetresPerAu = 149597870700.0;
constexpr double kSecondsPerDay = 86400.0;

double distance_m(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) * kMetresPerAu;
}
double speed_difference_m_s(const Vec3& a, const Vec3& b) {
  return distance_m(a, b) / kSecondsPerDay;
}

// 2025-03-14 00:00 TT, the oracle notes' test day.
const JulianDate kStart{2460748.5, 0.0};

// The bounds are set by ERFA's self-consistency, not by the interpolation: eraMoon98's velocity
// differs from the derivative of its position by ~4.7 mm/s (independent of the step: 0.18 m at
// 10 min, 0.018 m at 1 min), eraEpv00's Earth by ~1e-5 m/s.
TEST(TabulatedEphemeris, FollowsErfaWithinItsOwnConsistency) {
  const ErfaEphemeris erfa;
  auto table = TabulatedEphemeris::build(erfa, kStart, 1.0);
  ASSERT_TRUE(table.ok()) << table.error().message;
  EXPECT_EQ(table->name(), "erfa");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> day(0.0, 1.0);
  double worst_pos_m = 0.0, worst_vel_m_s = 0.0;
  for (int i = 0; i < 300; ++i) {
    const JulianDate tt{kStart.jd1, day(rng)};
    const EarthSun direct = *erfa.earth_sun(tt);
    const EarthSun interpolated = *table->earth_sun(tt);
    const PosVel moon_direct = *erfa.moon_geocentric(tt);
    const PosVel moon_interpolated = *table->moon_geocentric(tt);
    for (const auto& [d, t] : {std::pair{direct.earth_bary, interpolated.earth_bary},
                               std::pair{direct.sun_bary, interpolated.sun_bary},
                               std::pair{moon_direct, moon_interpolated}}) {
      worst_pos_m = std::max(worst_pos_m, distance_m(d.pos_au, t.pos_au));
      worst_vel_m_s = std::max(worst_vel_m_s, speed_difference_m_s(d.vel_au_d, t.vel_au_d));
    }
  }
  EXPECT_LT(worst_pos_m, 0.25);
  EXPECT_LT(worst_vel_m_s, 0.006);
}

TEST(TabulatedEphemeris, PointingThroughTheTableMatchesDirect) {
  const ErfaEphemeris erfa;
  const auto table = *TabulatedEphemeris::build(erfa, kStart, 1.0);
  auto utc = UtcInstant::from_calendar(2025, 3, 14, 6, 0, 0.0);
  const TimeScales t = *make_time_scales(*utc, 0.2, LeapSecondTable::builtin());
  const Observer o{46.189, -79.393, 300.0};
  const Epoch e1 = *make_epoch(erfa, t);
  const Epoch e2 = *make_epoch(table, t);
  const Place p1 = *observe_moon(erfa, e1, make_station(e1, o));
  const Place p2 = *observe_moon(table, e2, make_station(e2, o));
  // < 0.001″ and < 0.01 mm/s: nothing a pointing or a Doppler readout can see.
  EXPECT_NEAR(p1.az_deg, p2.az_deg, 0.001 / 3600.0);
  EXPECT_NEAR(p1.el_geometric_deg, p2.el_geometric_deg, 0.001 / 3600.0);
  EXPECT_NEAR(*p1.range_rate_km_s, *p2.range_rate_km_s, 1e-8);
}

TEST(TabulatedEphemeris, RefusesInstantsOutsideItsSpan) {
  const ErfaEphemeris erfa;
  const auto table = *TabulatedEphemeris::build(erfa, kStart, 0.5);
  EXPECT_TRUE(table.covers(kStart));
  EXPECT_TRUE(table.covers(JulianDate{kStart.jd1, 0.5}));
  EXPECT_FALSE(table.covers(JulianDate{kStart.jd1, -1e-6}));
  EXPECT_FALSE(table.covers(JulianDate{kStart.jd1, 0.6}));
  auto outside = table.moon_geocentric(JulianDate{kStart.jd1, 2.0});
  ASSERT_FALSE(outside.ok());
  EXPECT_NE(outside.error().message.find("does not cover"), std::string::npos);
  EXPECT_FALSE(table.earth_sun(JulianDate{kStart.jd1, std::nan("")}).ok());
}

TEST(TabulatedEphemeris, RejectsBadSpans) {
  const ErfaEphemeris erfa;
  EXPECT_FALSE(TabulatedEphemeris::build(erfa, kStart, 0.0).ok());
  EXPECT_FALSE(TabulatedEphemeris::build(erfa, kStart, 1.0, -1.0).ok());
  EXPECT_FALSE(TabulatedEphemeris::build(erfa, kStart, 1.0, std::nan("")).ok());
  EXPECT_FALSE(TabulatedEphemeris::build(erfa, kStart, 1e6, 1e-3).ok());
}

}  // namespace
}  // namespace azt::astro
