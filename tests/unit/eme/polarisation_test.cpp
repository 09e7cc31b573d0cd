// Spatial polarisation (docs/eme.md) with WSJT-X's definitions: the parallactic angle in
// directions where it is known, Dpol folded as a linear polarisation, MNR and its 25 dB cap.
#include "azt/eme/polarisation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::eme {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(ParallacticAngle, KnownDirections) {
  // On the meridian, south of the zenith, the sky's vertical is the antenna's: 0°.
  EXPECT_NEAR(parallactic_angle_deg(46.0, 180.0, 30.0), 0.0, 1e-12);
  // Rising due east on the horizon: 90° − latitude (90° on the equator).
  EXPECT_NEAR(parallactic_angle_deg(46.0, 90.0, 0.0), 44.0, 1e-12);
  EXPECT_NEAR(parallactic_angle_deg(0.0, 90.0, 0.0), 90.0, 1e-12);
  // Setting due west: the mirror image.
  EXPECT_NEAR(parallactic_angle_deg(46.0, 270.0, 0.0), -44.0, 1e-12);
  // Spherical trigonometry's closed form for an object on the horizon at azimuth A:
  // tan q = cos φ sin A / sin φ.
  const double q = std::atan2(std::cos(0.5) * std::sin(2.0), std::sin(0.5)) * 180.0 / kPi;
  EXPECT_NEAR(parallactic_angle_deg(0.5 * 180.0 / kPi, 2.0 * 180.0 / kPi, 0.0), q, 1e-9);
}

TEST(Dpol, FoldedLikeALinearPolarisation) {
  EXPECT_DOUBLE_EQ(dpol_deg(10.0, 30.0), 20.0);
  EXPECT_DOUBLE_EQ(dpol_deg(30.0, 10.0), -20.0);
  EXPECT_DOUBLE_EQ(dpol_deg(10.0, 200.0), 10.0) << "190° is 10° for a linear polarisation";
  EXPECT_DOUBLE_EQ(dpol_deg(0.0, 100.0), -80.0);
  EXPECT_DOUBLE_EQ(dpol_deg(0.0, 90.0), 90.0);
  EXPECT_DOUBLE_EQ(dpol_deg(0.0, -90.0), 90.0);
  EXPECT_DOUBLE_EQ(dpol_deg(-170.0, 170.0), -20.0);
  for (int i = 0; i <= 48; ++i) {
    for (int j = 0; j <= 32; ++j) {
      const double d = dpol_deg(-180.0 + 7.5 * i, -180.0 + 11.0 * j);
      EXPECT_GT(d, -90.0);
      EXPECT_LE(d, 90.0);
    }
  }
}

TEST(Mnr, NonReciprocityAndItsCap) {
  EXPECT_NEAR(mnr_db(0.0), 0.0, 1e-12);
  EXPECT_NEAR(mnr_db(30.0), 20.0 * std::log10(2.0), 1e-9);  // |cos 60°| = 0.5
  EXPECT_NEAR(mnr_db(45.0), 25.0, 1e-3) << "capped at 25 dB";
  EXPECT_NEAR(mnr_db(-30.0), mnr_db(30.0), 1e-12);
  EXPECT_NEAR(mnr_db(90.0), 0.0, 1e-9) << "crossed by 90°: the echo's sense is reversed, not lost";
}

}  // namespace
}  // namespace azt::eme
