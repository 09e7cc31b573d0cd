// The station's position from the GPS (docs/gps.md): a held 3D fix, averaged; what breaks a
// run; the distance that tells a moved antenna from a wandering fix; and what to adopt.
#include "azt/gnss/site_survey.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace azt::gnss {
namespace {

GpsFix fix3d(double lat, double lon, double alt) {
  return GpsFix{FixMode::Fix3d, lat, lon, alt, std::nullopt};
}

TEST(GroundDistance, KnownDistances) {
  EXPECT_NEAR(ground_distance_m({46.0, -79.0, 0}, {47.0, -79.0, 0}), 111195.0, 1.0);
  // London to Paris: 343.5 km on the sphere.
  EXPECT_NEAR(ground_distance_m({51.5074, -0.1278, 0}, {48.8566, 2.3522, 0}), 343.5e3, 1e3);
  // Across the antimeridian: 0.2° of longitude on the equator, not 359.8°.
  EXPECT_NEAR(ground_distance_m({0.0, 179.9, 0}, {0.0, -179.9, 0}), 22239.0, 1.0);
  EXPECT_DOUBLE_EQ(ground_distance_m({46.0, -79.0, 0}, {46.0, -79.0, 500}), 0.0);
}

TEST(SiteSurvey, TheAverageComesOnlyOnceTheFixHasHeld) {
  SiteSurvey survey({10.0, 4, 100.0});
  const std::vector<Site> seen{
      {46.0001, -79.0002, 300.0}, {46.0003, -79.0001, 302.0}, {45.9999, -79.0004, 299.0}};
  double t = 0.0;
  for (int round = 0; round < 4; ++round) {  // 12 fixes, 1 s apart: 0..11 s
    for (const Site& s : seen) {
      survey.on_fix(t, fix3d(s.lat_deg, s.lon_deg, s.alt_m), 8);
      EXPECT_EQ(survey.surveyed().has_value(), t >= 10.0) << t;
      t += 1.0;
    }
  }
  const auto site = survey.surveyed();
  ASSERT_TRUE(site.has_value());
  EXPECT_EQ(survey.fixes(), 12U);
  EXPECT_NEAR(site->lat_deg, (46.0001 + 46.0003 + 45.9999) / 3.0, 1e-9);
  EXPECT_NEAR(site->lon_deg, (-79.0002 - 79.0001 - 79.0004) / 3.0, 1e-9);
  EXPECT_NEAR(site->alt_m, (300.0 + 302.0 + 299.0) / 3.0, 1e-9);
}

TEST(SiteSurvey, A2dFixTooFewSatellitesOrASilenceRestartTheRun) {
  SiteSurvey survey({5.0, 4, 100.0});
  for (int t = 0; t <= 6; ++t) survey.on_fix(t, fix3d(46.0, -79.0, 300.0), 8);
  ASSERT_TRUE(survey.surveyed().has_value());
  survey.on_fix(7.0, GpsFix{FixMode::Fix2d, 46.0, -79.0, std::nullopt, std::nullopt}, 8);
  EXPECT_FALSE(survey.surveyed().has_value());
  EXPECT_EQ(survey.fixes(), 0U);
  for (int t = 8; t <= 14; ++t) survey.on_fix(t, fix3d(46.0, -79.0, 300.0), 8);
  ASSERT_TRUE(survey.surveyed().has_value());
  survey.on_fix(15.0, fix3d(46.0, -79.0, 300.0), 3);  // fewer than min_sats
  EXPECT_FALSE(survey.surveyed().has_value());
  for (int t = 16; t <= 22; ++t) survey.on_fix(t, fix3d(46.0, -79.0, 300.0), 4);
  ASSERT_TRUE(survey.surveyed().has_value());
  survey.on_fix(28.01, fix3d(47.0, -79.0, 300.0), 8);  // 6 s of silence, then a new place
  EXPECT_EQ(survey.fixes(), 1U) << "the run before the silence is not averaged in";
  EXPECT_FALSE(survey.surveyed().has_value());
}

TEST(SiteSurvey, NoFixOrA3dFixWithoutAltitudeRestartsTheRun) {
  SiteSurvey survey({2.0, 4, 100.0});
  for (int t = 0; t <= 2; ++t) survey.on_fix(t, fix3d(46.0, -79.0, 300.0), 8);
  ASSERT_TRUE(survey.surveyed().has_value());
  survey.on_fix(3.0, GpsFix{FixMode::None, 0.0, 0.0, std::nullopt, std::nullopt}, 8);
  EXPECT_EQ(survey.fixes(), 0U);
  EXPECT_FALSE(survey.surveyed().has_value());
  for (int t = 4; t <= 6; ++t) survey.on_fix(t, fix3d(46.0, -79.0, 300.0), 8);
  ASSERT_TRUE(survey.surveyed().has_value());
  survey.on_fix(7.0, GpsFix{FixMode::Fix3d, 46.0, -79.0, std::nullopt, std::nullopt}, 8);
  EXPECT_EQ(survey.fixes(), 0U);
}

TEST(SiteSurvey, FiveSecondsBetweenFixesKeepsTheRunSixRestartIt) {
  SiteSurvey survey({10.0, 4, 100.0});
  survey.on_fix(0.0, fix3d(46.0, -79.0, 300.0), 8);
  survey.on_fix(5.0, fix3d(46.0, -79.0, 300.0), 8);
  survey.on_fix(10.0, fix3d(46.0, -79.0, 300.0), 8);
  EXPECT_EQ(survey.fixes(), 3U);
  ASSERT_TRUE(survey.surveyed().has_value()) << "held 10 s with 5 s gaps";
  survey.on_fix(16.0, fix3d(46.0, -79.0, 300.0), 8);
  EXPECT_EQ(survey.fixes(), 1U);
  EXPECT_FALSE(survey.surveyed().has_value());
}

TEST(SiteSurvey, LongitudesAverageAcrossTheAntimeridian) {
  SiteSurvey survey({1.0, 4, 1e6});  // the two fixes are 430 m apart: no jump here
  survey.on_fix(0.0, fix3d(-17.0, 179.999, 10.0), 6);
  survey.on_fix(1.0, fix3d(-17.0, -179.997, 10.0), 6);
  const auto site = survey.surveyed();
  ASSERT_TRUE(site.has_value());
  EXPECT_NEAR(site->lon_deg, -179.999, 1e-9);  // not 0.001, half a world away
}

TEST(SiteSurvey, AMeanOnTheAntimeridianIsPlus180) {
  SiteSurvey survey({1.0, 4, 1e7});
  survey.on_fix(0.0, fix3d(0.0, -170.0, 0.0), 6);
  survey.on_fix(1.0, fix3d(0.0, 170.0, 0.0), 6);
  const auto site = survey.surveyed();
  ASSERT_TRUE(site.has_value());
  EXPECT_EQ(site->lon_deg, 180.0) << "(-180, 180]: -180 is written 180";
}

TEST(SiteDecision, EveryBranch) {
  const Site here{46.0, -79.0, 300.0};
  const Site half_metre{46.0 + 0.5 / 111195.0, -79.0, 300.0};
  const Site fifty_m{46.0 + 50.0 / 111195.0, -79.0, 300.0};
  const Site five_hundred_m{46.0 + 500.0 / 111195.0, -79.0, 300.0};
  const Site ninety_nine_m{46.0 + 99.0 / 111195.0, -79.0, 300.0};
  const Site hundred_one_m{46.0 + 101.0 / 111195.0, -79.0, 300.0};
  const Site two_metres{46.0 + 2.0 / 111195.0, -79.0, 300.0};
  EXPECT_EQ(decide_site(std::nullopt, here, true, 100.0), SiteDecision::Adopt);
  EXPECT_EQ(decide_site(here, half_metre, true, 100.0), SiteDecision::Keep);
  EXPECT_EQ(decide_site(here, fifty_m, true, 100.0), SiteDecision::Adopt);
  EXPECT_EQ(decide_site(here, five_hundred_m, true, 100.0), SiteDecision::Jump);
  EXPECT_EQ(decide_site(here, five_hundred_m, false, 100.0), SiteDecision::Adopt);
  EXPECT_EQ(decide_site(here, half_metre, false, 100.0), SiteDecision::Keep);
  EXPECT_EQ(decide_site(here, two_metres, true, 100.0), SiteDecision::Adopt);
  EXPECT_EQ(decide_site(here, ninety_nine_m, true, 100.0), SiteDecision::Adopt);
  EXPECT_EQ(decide_site(here, hundred_one_m, true, 100.0), SiteDecision::Jump);
  EXPECT_EQ(decide_site(here, five_hundred_m, true, 1000.0), SiteDecision::Adopt);
  EXPECT_EQ(to_string(SiteDecision::Jump), "jump");
  EXPECT_EQ(to_string(SiteDecision::Keep), "keep");
  EXPECT_EQ(to_string(SiteDecision::Adopt), "adopt");
}

TEST(SiteSurvey, AFixFarFromTheMeanStartsANewSurveyInsteadOfCreeping) {
  SiteSurvey survey({2.0, 4, 100.0});
  for (int t = 0; t <= 3; ++t) survey.on_fix(t, fix3d(46.0, -79.0, 300.0), 8);
  ASSERT_TRUE(survey.surveyed().has_value());
  const double moved_lat = 46.0 + 500.0 / 111195.0;
  survey.on_fix(4.0, fix3d(moved_lat, -79.0, 300.0), 8);
  EXPECT_EQ(survey.fixes(), 1U);
  EXPECT_FALSE(survey.surveyed().has_value());
  for (int t = 5; t <= 6; ++t) survey.on_fix(t, fix3d(moved_lat, -79.0, 300.0), 8);
  ASSERT_TRUE(survey.surveyed().has_value());
  EXPECT_NEAR(survey.surveyed()->lat_deg, moved_lat, 1e-12);  // all of the new place
  // A fix 50 m off (inside jump_m) is noise in the average, not a move.
  survey.on_fix(7.0, fix3d(moved_lat + 50.0 / 111195.0, -79.0, 300.0), 8);
  EXPECT_EQ(survey.fixes(), 4U);
}

}  // namespace
}  // namespace azt::gnss
