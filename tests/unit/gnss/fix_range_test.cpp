// A GPS fix off the Earth is refused, never wrapped (docs/gps.md; from gpsd, longitude 500 had
// once been saved as the station's 140.0 and -200 as 160.0).
#include "azt/gnss/fix_range.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "azt/gnss/site_survey.hpp"

namespace azt::gnss {
namespace {

GpsFix fix3d(double lat, double lon, double alt) {
  return GpsFix{FixMode::Fix3d, lat, lon, alt, std::nullopt};
}

TEST(FixRange, PlacesOnTheEarthPassToTheirEdges) {
  EXPECT_FALSE(out_of_range(fix3d(46.0, -79.0, 300.0)));
  EXPECT_FALSE(out_of_range(fix3d(90.0, 180.0, -430.0)));
  EXPECT_FALSE(out_of_range(fix3d(-90.0, -180.0, 5600.0)));
  EXPECT_FALSE(out_of_range(GpsFix{FixMode::Fix2d, 46.0, -79.0, std::nullopt, std::nullopt}));
}

TEST(FixRange, EachCoordinateOutOfItsRangeIsRefusedWithItsName) {
  const double inf = std::numeric_limits<double>::infinity();
  const auto lon = out_of_range(fix3d(46.0, 500.0, 300.0));
  ASSERT_TRUE(lon);
  EXPECT_NE(lon->find("longitude 500"), std::string::npos) << *lon;
  EXPECT_TRUE(out_of_range(fix3d(46.0, -200.0, 300.0)));
  EXPECT_TRUE(out_of_range(fix3d(95.0, 10.0, 300.0)));
  EXPECT_TRUE(out_of_range(fix3d(-90.5, 10.0, 300.0)));
  EXPECT_TRUE(out_of_range(fix3d(46.0, 10.0, inf)));
  EXPECT_TRUE(out_of_range(fix3d(46.0, 10.0, 20000.0)));
  EXPECT_TRUE(out_of_range(fix3d(46.0, std::nan(""), 300.0)));
}

TEST(FixRange, AFixWithoutAPlaceIsNeverOutOfRange) {
  EXPECT_FALSE(out_of_range(GpsFix{FixMode::None, 500.0, 500.0, std::nullopt, std::nullopt}));
}

TEST(FixRange, ASurveyOfOutOfRangeLongitudesNeverGivesASite) {
  for (const double lon : {500.0, -200.0, 180.0001}) {
    SiteSurvey survey({10.0, 4, 100.0});
    for (int t = 0; t <= 20; ++t) survey.on_fix(t, fix3d(46.0, lon, 300.0), 8);
    EXPECT_FALSE(survey.surveyed()) << lon;
    EXPECT_EQ(survey.fixes(), 0U) << lon;
  }
}

TEST(FixRange, AnOutOfRangeFixRestartsARunningSurvey) {
  SiteSurvey survey({10.0, 4, 100.0});
  for (int t = 0; t <= 5; ++t) survey.on_fix(t, fix3d(46.0, 140.0, 300.0), 8);
  EXPECT_EQ(survey.fixes(), 6U);
  survey.on_fix(6, fix3d(46.0, 500.0, 300.0), 8);
  EXPECT_EQ(survey.fixes(), 0U);
}

}  // namespace
}  // namespace azt::gnss
