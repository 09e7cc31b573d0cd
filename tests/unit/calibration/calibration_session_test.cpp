// The calibration session's steps (docs/calibration.md): a source gets its scan, a raster when
// that finds nothing, a scan centred on what was found, then rows in the log; a source that is
// not found waits; a session rebuilt from its log carries on.
#include "azt/calibration/calibration_session.hpp"

#include <gtest/gtest.h>

namespace azt::calibration {
namespace {

using Kind = SessionStep::Kind;

const std::vector<control::AzEl> kAt{{100.0, 30.0}, {250.0, 60.0}};

SessionPlanner planner(std::size_t max_scans = 10) {
  PlanSettings s;
  s.scan_s = 600.0;
  s.max_scans = max_scans;
  s.every_s = 3600.0;
  return SessionPlanner(
      {{"sun", 40.0, 0.53, true}, {"casa", 20.0, 0.0, false}},
      [](std::size_t i, double) -> std::optional<control::AzEl> {
        return i < kAt.size() ? std::optional(kAt[i]) : std::nullopt;
      },
      SiteLimits{}, s);
}

SessionSetup setup() {
  SessionSetup s;
  s.spec.beamwidth_deg = 1.6;
  s.epoch = *astro::parse_iso8601_utc("2025-06-01T12:00:00Z");
  return s;
}

ScanResult found(const SkyOffset& peak, const control::AzEl& at, double t_s) {
  ScanResult r;
  ScanFit f;
  f.peak = peak;
  f.peak_std = {0.003, 0.004};
  f.width_xel_deg = f.width_el_deg = 1.6;
  f.peak_db = 20.0;
  f.noise_db = 0.05;
  r.fit = f;
  r.xel_moment_s = t_s - 300.0;
  r.el_moment_s = t_s - 100.0;
  r.sky_xel = at;
  r.sky_el = at;
  return r;
}

ScanResult nothing() {
  ScanResult r;
  r.fit = fail("the peak is not 5 noise rms above the baseline");
  return r;
}

TEST(CalibrationSession, ScansThenRefinesThenLogsTwoRowsOfACrossScan) {
  CalibrationSession s(planner(), setup());
  const SessionStep first = s.next(0.0);
  ASSERT_EQ(first.kind, Kind::Scan);
  EXPECT_EQ(first.source, 0U);  // the Sun is due
  EXPECT_EQ(first.spec.kind, ScanKind::Cross);
  EXPECT_EQ(s.next(10.0).source, 0U);  // the same step while it runs
  EXPECT_TRUE(s.scan_ended(500.0, found({0.3, -0.2}, kAt[0], 500.0)).empty());
  const SessionStep refine = s.next(500.0);
  ASSERT_EQ(refine.kind, Kind::Scan);
  EXPECT_DOUBLE_EQ(refine.centre.xel_deg, 0.3);
  EXPECT_DOUBLE_EQ(refine.centre.el_deg, -0.2);
  const auto rows = s.scan_ended(1000.0, found({0.31, -0.21}, kAt[0], 1000.0));
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_EQ(rows[0].source, "sun");
  EXPECT_EQ(rows[0].measured, Measured::Az);
  EXPECT_EQ(astro::format_iso8601_utc(rows[1].utc), "2025-06-01T12:15:00.000Z");
  EXPECT_NEAR(rows[1].del_deg, -0.21, 1e-3);
  EXPECT_EQ(s.log().size(), 2U);
  ASSERT_EQ(s.history().size(), 1U);
  EXPECT_EQ(s.history()[0].scans, 2U);
  EXPECT_EQ(s.planner().fitted_scans(), 1U);
  // Next: Cas A (the Sun is not due for an hour).
  EXPECT_EQ(s.next(1000.0).source, 1U);
}

TEST(CalibrationSession, SearchesWithARasterWhenTheScanFindsNothing) {
  CalibrationSession s(planner(), setup());
  ASSERT_EQ(s.next(0.0).kind, Kind::Scan);
  s.scan_ended(400.0, nothing());
  const SessionStep search = s.next(400.0);
  EXPECT_EQ(search.spec.kind, ScanKind::Raster);
  EXPECT_EQ(search.spec.points_per_line, 7U);
  EXPECT_DOUBLE_EQ(search.spec.half_span_beams, 3.0);
  s.scan_ended(900.0, found({1.5, 0.8}, kAt[0], 900.0));
  const SessionStep refine = s.next(900.0);
  EXPECT_EQ(refine.spec.kind, ScanKind::Cross);
  EXPECT_DOUBLE_EQ(refine.centre.xel_deg, 1.5);
  EXPECT_EQ(s.scan_ended(1400.0, found({1.52, 0.79}, kAt[0], 1400.0)).size(), 2U);
  EXPECT_EQ(s.history()[0].scans, 3U);
}

TEST(CalibrationSession, ASourceNotFoundIsRecordedAndWaits) {
  CalibrationSession s(planner(), setup());
  ASSERT_EQ(s.next(0.0).source, 0U);
  s.scan_ended(400.0, nothing());
  EXPECT_TRUE(s.scan_ended(900.0, nothing()).empty());
  ASSERT_EQ(s.history().size(), 1U);
  EXPECT_EQ(s.history()[0].refused, "the peak is not 5 noise rms above the baseline");
  EXPECT_FALSE(s.scanning());
  EXPECT_EQ(s.next(900.0).source, 1U);  // not the Sun again before retry_s
}

TEST(CalibrationSession, AScanWithoutItsMomentsIsNotLogged) {
  CalibrationSession s(planner(), setup());
  s.next(0.0);
  ScanResult r = found({0.1, 0.1}, kAt[0], 500.0);
  r.sky_el.reset();
  s.scan_ended(500.0, r);
  EXPECT_TRUE(s.scan_ended(1000.0, r).empty());
  EXPECT_EQ(s.history()[0].refused, "the source's position at the scan's moments is unknown");
}

TEST(CalibrationSession, CarriesOnFromTheLogOfAnEarlierOne) {
  CalibrationSession first(planner(), setup());
  first.next(0.0);
  first.scan_ended(500.0, found({0.3, -0.2}, kAt[0], 500.0));
  first.scan_ended(1000.0, found({0.3, -0.2}, kAt[0], 1000.0));
  // A restart: the same session from its log. The Sun was scanned at 900 s (its last row):
  // not due again before 4500 s, so Cas A comes first; the coverage is the same.
  const CalibrationSession again(planner(), setup(), first.log());
  EXPECT_EQ(again.log().size(), 2U);
  EXPECT_EQ(again.planner().fitted_scans(), 1U);
  EXPECT_DOUBLE_EQ(again.planner().sky_error(), first.planner().sky_error());
  CalibrationSession resumed(planner(), setup(), first.log());
  EXPECT_EQ(resumed.next(1000.0).source, 1U);
}

TEST(CalibrationSession, WaitsWhenNothingIsWorthItAndEndsAtMaxScans) {
  CalibrationSession s(planner(1), setup());
  s.next(0.0);
  s.scan_ended(500.0, found({0.3, -0.2}, kAt[0], 500.0));
  s.scan_ended(1000.0, found({0.3, -0.2}, kAt[0], 1000.0));
  EXPECT_EQ(s.next(1000.0).kind, Kind::Done);
  // A session of a source below the horizon only waits.
  SessionPlanner low(
      {{"low", 30.0, 0.0, false}},
      [](std::size_t, double) {
        return std::optional(control::AzEl{0.0, -5.0});
      },
      SiteLimits{}, PlanSettings{});
  CalibrationSession waiting(low, setup());
  const SessionStep w = waiting.next(100.0);
  EXPECT_EQ(w.kind, Kind::Wait);
  EXPECT_DOUBLE_EQ(w.until_s, 100.0 + PlanSettings{}.wait_s);
}

TEST(CalibrationSession, ExpectedTimeOfASourceCountsItsPoints) {
  SessionSetup s = setup();
  s.spec.points_per_line = 21;
  s.timing.settle_s = 1.0;
  s.timing.dwell_s = 4.0;
  // 84 points there and back (twice 2 × 21), 6.25 s each, twice (the refining scan).
  EXPECT_DOUBLE_EQ(CalibrationSession::expected_source_s(s), 2.0 * 84.0 * 6.25);
}

}  // namespace
}  // namespace azt::calibration
