#include "azt/control/axis_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <random>

namespace azt::control {
namespace {

TEST(AzimuthRange, Validates) {
  EXPECT_TRUE(AzimuthRange::make(0, 360).ok());
  EXPECT_TRUE(AzimuthRange::make(0, 450).ok());
  EXPECT_TRUE(AzimuthRange::make(-180, 540).ok());
  EXPECT_FALSE(AzimuthRange::make(0, 350).ok());  // cannot reach every azimuth
  EXPECT_FALSE(AzimuthRange::make(0, 800).ok());
  EXPECT_FALSE(AzimuthRange::make(360, 0).ok());
  EXPECT_FALSE(ElevationRange::make(0, 200).ok());
  EXPECT_TRUE(ElevationRange::make(0, 180).ok());
}

TEST(PlanAzimuth, PlainRotatorNeverCrossesItsStopAtNorth) {
  const AzimuthRange r{0, 360};
  // From 350° to 10°: the short way crosses the stop at 0/360, so the rotator goes round.
  EXPECT_DOUBLE_EQ(plan_azimuth(350, 10, r), 10);
  EXPECT_DOUBLE_EQ(plan_azimuth(10, 350, r), 350);
  EXPECT_DOUBLE_EQ(plan_azimuth(100, -20, r), 340);
}

TEST(PlanAzimuth, OverlapRotatorTakesTheShortLegalWay) {
  const AzimuthRange r{0, 450};
  EXPECT_DOUBLE_EQ(plan_azimuth(350, 10, r), 370);  // continue through north into the overlap
  EXPECT_DOUBLE_EQ(plan_azimuth(370, 350, r), 350);
  EXPECT_DOUBLE_EQ(plan_azimuth(20, 80, r), 80);  // 440 is legal but farther
  EXPECT_DOUBLE_EQ(plan_azimuth(440, 80, r), 440);
  const AzimuthRange wide{-180, 540};
  EXPECT_DOUBLE_EQ(plan_azimuth(-170, 180, wide), -180);
  EXPECT_DOUBLE_EQ(plan_azimuth(530, 170, wide), 530);
}

TEST(PlanAzimuth, AlwaysInsideTheRangeAndEquivalent) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> any(-1000, 1000);
  for (const AzimuthRange r : {AzimuthRange{0, 360}, AzimuthRange{0, 450}, AzimuthRange{-180, 540},
                               AzimuthRange{270, 720}}) {
    for (int i = 0; i < 2000; ++i) {
      const double current = r.min_deg + wrap_360(any(rng)) * (r.max_deg - r.min_deg) / 360.0;
      const double sky = any(rng);
      const double mount = plan_azimuth(current, sky, r);
      EXPECT_GE(mount, r.min_deg);
      EXPECT_LE(mount, r.max_deg);
      EXPECT_NEAR(wrap_360(mount), wrap_360(sky), 1e-9);
    }
  }
}

TEST(PlanElevation, RefusesTargetsOutsideTheTravel) {
  const ElevationRange r{0, 90};
  EXPECT_EQ(plan_elevation(45, r), 45);
  EXPECT_FALSE(plan_elevation(-0.1, r).has_value());
  EXPECT_FALSE(plan_elevation(91, r).has_value());
  EXPECT_FALSE(plan_elevation(std::nan(""), r).has_value());
}

TEST(Wrap360, Wraps) {
  EXPECT_DOUBLE_EQ(wrap_360(-10), 350);
  EXPECT_DOUBLE_EQ(wrap_360(720), 0);
  EXPECT_DOUBLE_EQ(wrap_360(359.5), 359.5);
  EXPECT_LT(wrap_360(-1e-17), 360.0);
}

}  // namespace
}  // namespace azt::control
