// The sky behind the Moon and Dgrd (docs/eme.md), as WSJT-X defines them: the table's 2° bins
// and their edges, the scaling with frequency, and Dgrd's zero at perigee in the coldest sky.
#include "azt/eme/sky_temperature.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::eme {
namespace {

TEST(Tsky144, TheTablesBins) {
  EXPECT_DOUBLE_EQ(tsky_144mhz_k(2.0), 234.0) << "bin 1: 1° to 3°";
  EXPECT_DOUBLE_EQ(tsky_144mhz_k(1.0), 234.0) << "nint(0.5) = 1";
  EXPECT_DOUBLE_EQ(tsky_144mhz_k(0.99), 231.0) << "below 1°: bin 180";
  EXPECT_DOUBLE_EQ(tsky_144mhz_k(359.5), 231.0) << "nint(179.75) = 180";
  EXPECT_DOUBLE_EQ(tsky_144mhz_k(272.0), 2836.0) << "bin 136, near the galactic centre";
  EXPECT_DOUBLE_EQ(tsky_144mhz_k(268.0), 3038.0) << "bin 134: the table's peak";
  EXPECT_DOUBLE_EQ(tsky_144mhz_k(138.0), 196.0) << "bin 69: the table's coldest";
  double hottest = 0.0;
  for (int i = 0; i < 1440; ++i) hottest = std::fmax(hottest, tsky_144mhz_k(0.25 * i));
  EXPECT_DOUBLE_EQ(hottest, 3038.0);
}

TEST(Tsky, ScaledWithTheSpectralIndex) {
  EXPECT_DOUBLE_EQ(tsky_k(2.0, 144.0), 234.0);
  EXPECT_NEAR(tsky_k(2.0, 432.0), (234.0 - 2.7) * std::pow(1.0 / 3.0, 2.6) + 2.7, 1e-9);
  EXPECT_NEAR(tsky_k(2.0, 10368.0), 2.7, 0.01) << "at 10 GHz the sky is the background";
  EXPECT_NEAR(cold_sky_k(408.0), 13.0, 1e-12);
  EXPECT_NEAR(cold_sky_k(144.0), 13.0 * std::pow(408.0 / 144.0, 2.6), 1e-9);
}

TEST(Dgrd, ZeroAtPerigeeInTheColdestSky) {
  EXPECT_NEAR(moon_distance_db(kPerigeeKm), 0.0, 1e-12);
  EXPECT_NEAR(moon_distance_db(406700.0), -2.27, 0.01) << "apogee";
  EXPECT_NEAR(dgrd_db(cold_sky_k(144.0), 144.0, kPerigeeKm), 0.0, 1e-12);
  // The galactic centre on 2 m: Tsys 3118 K against 275 K (−10.5 dB), and −1.3 dB for the
  // mean distance.
  const double t = tsky_k(268.0, 144.0);
  EXPECT_NEAR(
      dgrd_db(t, 144.0, 384400.0),
      -10.0 * std::log10((t + 80.0) / (cold_sky_k(144.0) + 80.0)) + moon_distance_db(384400.0),
      1e-12);
  EXPECT_NEAR(dgrd_db(t, 144.0, 384400.0), -11.84, 0.01);
}

TEST(EclipticLongitude, FromRightAscensionAndDeclination) {
  EXPECT_NEAR(ecliptic_longitude_deg(0.0, 0.0), 0.0, 1e-12);
  EXPECT_NEAR(ecliptic_longitude_deg(180.0, 0.0), 180.0, 1e-12);
  // The solstice points: RA 90°, Dec +ε is longitude 90°; RA 270°, Dec −ε is 270°.
  EXPECT_NEAR(ecliptic_longitude_deg(90.0, kTskyTableObliquityDeg), 90.0, 1e-9);
  EXPECT_NEAR(ecliptic_longitude_deg(270.0, -kTskyTableObliquityDeg), 270.0, 1e-9);
  // The galactic centre (RA 266.4°, Dec −29.0°) lies near ecliptic longitude 266.8°.
  EXPECT_NEAR(ecliptic_longitude_deg(266.405, -28.936), 266.8, 0.1);
}

}  // namespace
}  // namespace azt::eme
