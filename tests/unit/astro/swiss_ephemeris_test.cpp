// The Swiss Ephemeris adapter on its own: files found or refused, and states in the frame the
// reduction expects (ICRS, equatorial, geometric). A frame slip — libswe defaults to ecliptic
// coordinates — shows up as degrees against ERFA's independent theories.
#include <gtest/gtest.h>

#include <cmath>

#include "azt/astro/erfa_ephemeris.hpp"
#ifdef AZT_HAVE_SWISS
#include "azt/astro/swiss_ephemeris.hpp"
#endif

namespace azt::astro {
namespace {

#ifdef AZT_HAVE_SWISS
constexpr double kKmPerAu = 149597870.7;

double angle_arcsec(const Vec3& a, const Vec3& b) {
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const Vec3 cross{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::hypot(cross[0], cross[1], cross[2]), dot) * 206264.806;
}

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

TEST(SwissEphemeris, RefusesAMissingDataDirectory) {
  auto eph = SwissEphemeris::open("/nonexistent/azeltrack-test");
  ASSERT_FALSE(eph.ok());
  EXPECT_NE(eph.error().message.find("not found"), std::string::npos) << eph.error().message;
  ASSERT_TRUE(SwissEphemeris::open().ok());  // back to the default path for later tests
}

TEST(SwissEphemeris, AgreesWithErfaTheoriesInTheSameFrame) {
  auto swiss = SwissEphemeris::open();
  ASSERT_TRUE(swiss.ok()) << swiss.error().message;
  const ErfaEphemeris erfa;
  for (double day : {-9000.0, 0.0, 9131.25, 12000.5}) {  // 1975 … 2032 around J2000
    const JulianDate tt{2451545.0, day};
    const PosVel ms = *swiss->moon_geocentric(tt);
    const PosVel me = *erfa.moon_geocentric(tt);
    // eraMoon98: 18″ worst, 32 km worst against ELP/MPP02 (erfa moon98.c).
    EXPECT_LT(angle_arcsec(ms.pos_au, me.pos_au), 20.0) << day;
    EXPECT_NEAR(std::hypot(ms.pos_au[0], ms.pos_au[1], ms.pos_au[2]) * kKmPerAu,
                std::hypot(me.pos_au[0], me.pos_au[1], me.pos_au[2]) * kKmPerAu, 35.0)
        << day;
    const EarthSun ss = *swiss->earth_sun(tt);
    const EarthSun se = *erfa.earth_sun(tt);
    // eraEpv00: ≤ 0.015″ in the Sun's direction seen from the Earth.
    EXPECT_LT(angle_arcsec(minus(ss.sun_bary.pos_au, ss.earth_bary.pos_au),
                           minus(se.sun_bary.pos_au, se.earth_bary.pos_au)),
              0.05)
        << day;
    EXPECT_LT(angle_arcsec(ss.earth_bary.vel_au_d, se.earth_bary.vel_au_d), 0.1) << day;
  }
}
#else
TEST(SwissEphemeris, NotBuiltIn) { GTEST_SKIP() << "built without libswe"; }
#endif

}  // namespace
}  // namespace azt::astro
