// The Moon's EME conditions put together (docs/eme.md): angular separation, the lit fraction,
// and how the station's and a DX station's places become Dpol, MNR, Tsky and Dgrd.
#include "azt/eme/moon_conditions.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/eme/polarisation.hpp"
#include "azt/eme/sky_temperature.hpp"

namespace azt::eme {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Separation, StableAtEveryScale) {
  EXPECT_NEAR(separation_deg(0.0, 0.0, 90.0, 0.0), 90.0, 1e-12);
  EXPECT_NEAR(separation_deg(10.0, 20.0, 190.0, -20.0), 180.0, 1e-9);
  EXPECT_NEAR(separation_deg(10.0, 89.9, 190.0, 89.9), 0.2, 1e-9) << "across the pole";
  EXPECT_NEAR(separation_deg(100.0, 30.0, 100.0 + 1.0 / 3600.0, 30.0),
              std::cos(30.0 * kPi / 180.0) / 3600.0, 1e-12)
      << "an arcsecond of RA";
}

TEST(Illumination, NewFullAndQuarter) {
  constexpr double kMoonKm = 384400.0;
  constexpr double kSunKm = 1.496e8;
  EXPECT_NEAR(illuminated_fraction(0.0, kMoonKm, kSunKm), 0.0, 1e-12);
  EXPECT_NEAR(illuminated_fraction(180.0, kMoonKm, kSunKm), 1.0, 1e-12);
  // At 90° elongation the phase angle is 90° less the Sun's angle seen across the Moon's
  // distance (0.147°): cos i = Δ/√(Δ² + R²).
  EXPECT_NEAR(illuminated_fraction(90.0, kMoonKm, kSunKm),
              0.5 + 0.5 * kMoonKm / std::hypot(kMoonKm, kSunKm), 1e-12);
}

astro::Place place(double az, double el, double ra, double dec, double km) {
  astro::Place p;
  p.az_deg = az;
  p.el_geometric_deg = el;
  p.ra_deg = ra;
  p.dec_deg = dec;
  p.distance_km = km;
  return p;
}

TEST(MoonConditions, FromThePlaces) {
  MoonInputs in;
  in.lat_deg = 46.19;
  in.moon = place(120.0, 25.0, 200.0, -10.0, 370000.0);
  in.sun = place(300.0, -20.0, 20.0, 10.0, 1.48e8);
  in.freq_mhz = 432.0;
  MoonConditions c = moon_conditions(in);
  EXPECT_DOUBLE_EQ(c.parallactic_deg, parallactic_angle_deg(46.19, 120.0, 25.0));
  EXPECT_DOUBLE_EQ(c.dpol_deg, 0.0) << "self echoes: no spatial offset";
  EXPECT_FALSE(c.dx_dpol_deg.has_value());
  EXPECT_FALSE(c.mnr_db.has_value());
  EXPECT_DOUBLE_EQ(c.ecliptic_lon_deg, ecliptic_longitude_deg(200.0, -10.0));
  EXPECT_DOUBLE_EQ(c.tsky_k, tsky_k(c.ecliptic_lon_deg, 432.0));
  EXPECT_DOUBLE_EQ(c.dgrd_db, dgrd_db(c.tsky_k, 432.0, 370000.0));
  EXPECT_NEAR(c.sun_sep_deg, 180.0, 1e-9);
  EXPECT_GT(c.illumination, 0.999);

  in.dx_lat_deg = -33.87;
  in.dx_moon = place(60.0, 40.0, 200.1, -10.0, 371000.0);
  c = moon_conditions(in);
  ASSERT_TRUE(c.dx_dpol_deg.has_value());
  EXPECT_DOUBLE_EQ(*c.dx_dpol_deg,
                   dpol_deg(c.parallactic_deg, parallactic_angle_deg(-33.87, 60.0, 40.0)));
  EXPECT_DOUBLE_EQ(*c.mnr_db, mnr_db(*c.dx_dpol_deg));
}

TEST(MoonConditions, EchoWidthsNeedTheMinuteLaterPlaces) {
  MoonInputs in;
  in.lat_deg = 46.19;
  in.moon = place(120.0, 25.0, 200.0, -10.0, 370000.0);
  in.sun = place(300.0, -20.0, 20.0, 10.0, 1.48e8);
  in.freq_mhz = 1296.0;
  in.tt_jd = 2460750.5;
  EXPECT_FALSE(moon_conditions(in).width_hz.has_value());
  in.moon_minute_later = place(120.2, 25.1, 200.01, -10.003, 370010.0);
  MoonConditions c = moon_conditions(in);
  ASSERT_TRUE(c.width_hz.has_value());
  EXPECT_GT(*c.width_hz, 0.0);
  EXPECT_FALSE(c.dx_width_hz.has_value()) << "no DX";
  in.dx_lat_deg = -33.87;
  in.dx_moon = place(60.0, 40.0, 200.1, -10.0, 371000.0);
  in.dx_moon_minute_later = place(60.2, 40.1, 200.11, -10.002, 371005.0);
  c = moon_conditions(in);
  ASSERT_TRUE(c.dx_width_hz.has_value());
  EXPECT_GT(*c.dx_width_hz, 0.0);
  // Width scales with frequency.
  in.freq_mhz = 2592.0;
  EXPECT_NEAR(*moon_conditions(in).width_hz, 2.0 * *c.width_hz, 1e-9);
}

}  // namespace
}  // namespace azt::eme
