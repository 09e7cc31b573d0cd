// The station moved (the console's grid, or the GPS survey) while a satellite is followed: the
// pass is planned again from the new place, except during a pass, which is finished as planned
// (a re-plan could swing the antenna to the other wrap side mid-pass).
#include "station/satellite_tracker.hpp"

#include <gtest/gtest.h>

#include <string>

#include "azt/astro/time_scales.hpp"

namespace azt::app {
namespace {

constexpr double kEpochUnixS = 1709296200.0;  // 2024-03-01 12:30 UTC, the element set's epoch

SatelliteTracker iss_tracker(const astro::Observer& site,
                             const track::MountGeometry& mount = track::MountGeometry{}) {
  SatelliteSettings s;
  s.mount = mount;
  s.site = site;
  SatelliteTracker t(s, [](const std::string&) {});
  t.adopt(SatelliteCatalogue::load(AZT_TEST_DATA_DIR "/sat/iss_2024.tle"), kEpochUnixS);
  return t;
}

std::string aos(SatelliteTracker& t, double unix_s) {
  control::AzEl rate;
  (void)t.demand(unix_s, 0.0, rate);
  const auto st = t.status(unix_s);
  return st.contains("aos") ? st["aos"].get<std::string>() : "none";
}

double unix_of(const nlohmann::json& iso) {
  return astro::parse_iso8601_utc(iso.get<std::string>())->unix_seconds();
}

const astro::Observer kFn06{46.18958, -79.39375, 301.0};
const astro::Observer kSydney{-33.8688, 151.2093, 50.0};

TEST(SatelliteTrackerAge, StaleElementsAreMarkedAndTooOldOnesNotTracked) {
  SatelliteTracker t = iss_tracker(kFn06);
  const double day = 86400.0;
  ASSERT_TRUE(t.follow("25544", kEpochUnixS + 20 * day, 0.0));
  const auto st = t.status(kEpochUnixS + 20 * day);
  EXPECT_TRUE(st["stale"].get<bool>());
  EXPECT_TRUE(st["refused"].is_null());
  const auto listed = t.list(kEpochUnixS + 20 * day).at(0);
  EXPECT_TRUE(listed["stale"].get<bool>());
  // Past refuse_days: not followed, and the reason says why and what to do.
  const auto refused = t.follow("ISS", kEpochUnixS + 61 * day, 0.0);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().message,
            "the elements of ISS (ZARYA) are 61.0 days from their epoch (beyond [satellites] "
            "refuse_days = 60): not tracked; fetch fresh ones");
  // Followed while fresh, then aged past the limit: no new pass is planned.
  control::AzEl rate;
  const control::Demand d = t.demand(kEpochUnixS + 62 * day, 0.0, rate);
  EXPECT_FALSE(d.position.has_value());
  EXPECT_NE(d.reason.find("refuse_days"), std::string::npos) << d.reason;
  EXPECT_FALSE(t.status(kEpochUnixS + 62 * day)["refused"].is_null());
}

TEST(SatelliteTrackerSite, ANewPlaceIsPlannedFromBeforeThePass) {
  SatelliteTracker t = iss_tracker(kFn06);
  ASSERT_TRUE(t.follow("25544", kEpochUnixS, 0.0));
  const std::string here = aos(t, kEpochUnixS);
  ASSERT_NE(here, "none");
  t.set_site(kSydney);
  const std::string there = aos(t, kEpochUnixS + 1.0);
  EXPECT_NE(there, "none");
  EXPECT_NE(there, here) << "the ISS rises at another time over Sydney";
  EXPECT_EQ(t.status(kEpochUnixS + 1.0)["phase"], "waiting for AOS");
}

TEST(SatelliteTrackerSite, APassUnderWayIsFinishedAsPlanned) {
  SatelliteTracker t = iss_tracker(kFn06);
  ASSERT_TRUE(t.follow("25544", kEpochUnixS, 0.0));
  (void)aos(t, kEpochUnixS);
  // Into the pass: a minute after AOS.
  const auto first = t.status(kEpochUnixS);
  const double aos_s = unix_of(first["aos"]);
  const double los_s = unix_of(first["los"]);
  const double mid = aos_s + 60.0;
  ASSERT_EQ(aos(t, mid), first["aos"]);
  ASSERT_EQ(t.status(mid)["phase"], "tracking");
  t.set_site(kSydney);
  EXPECT_EQ(aos(t, mid + 1.0), first["aos"]) << "the pass under way keeps its plan";
  EXPECT_EQ(t.status(mid + 1.0)["phase"], "tracking");
  // After LOS the next pass is planned from Sydney: it differs from FN06's next.
  SatelliteTracker home = iss_tracker(kFn06);
  ASSERT_TRUE(home.follow("25544", los_s + 10.0, 0.0));
  const std::string next_here = aos(home, los_s + 10.0);
  const std::string next_there = aos(t, los_s + 10.0);
  EXPECT_NE(next_there, first["aos"].get<std::string>());
  EXPECT_NE(next_there, next_here);
}

// docs/satellites.md: the loss a pass will cost is known before AOS. A rotator with 90° of travel
// cannot follow the ISS across the sky; a flip mount follows every pass.
TEST(SatelliteTrackerLoss, ThePlannedLossIsReportedBeforeAOS) {
  track::MountGeometry short_travel;
  short_travel.az = control::AzimuthRange{0.0, 90.0};
  short_travel.loss_error_deg = 5.0;
  SatelliteTracker t = iss_tracker(kFn06, short_travel);
  ASSERT_TRUE(t.follow("25544", kEpochUnixS, 0.0));
  (void)aos(t, kEpochUnixS);
  const auto st = t.status(kEpochUnixS);
  ASSERT_EQ(st["phase"], "waiting for AOS");
  const auto& loss = st["planned_loss"];
  EXPECT_GT(loss["seconds"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(loss["beyond_deg"].get<double>(), 5.0);
  EXPECT_GE(unix_of(loss["from"]), unix_of(st["aos"]) - 1.0);
  EXPECT_LE(unix_of(loss["to"]), unix_of(st["los"]) + 1.0);
  EXPECT_LE(loss["seconds"].get<double>(), unix_of(loss["to"]) - unix_of(loss["from"]) + 1e-6);

  track::MountGeometry flip;
  flip.el = control::ElevationRange{0.0, 180.0};
  SatelliteTracker f = iss_tracker(kFn06, flip);
  ASSERT_TRUE(f.follow("25544", kEpochUnixS, 0.0));
  (void)aos(f, kEpochUnixS);
  const auto none = f.status(kEpochUnixS)["planned_loss"];
  EXPECT_EQ(none["seconds"].get<double>(), 0.0);
  EXPECT_TRUE(none["from"].is_null());
}

}  // namespace
}  // namespace azt::app
