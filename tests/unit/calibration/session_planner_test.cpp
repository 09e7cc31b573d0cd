// The calibration session's plan (docs/calibration.md): the scans spread over the sky better
// than scanning the brightest source, never go below the site's limits, the Sun comes every N
// minutes, and a source that failed waits. The sky here is a few sources turning about the pole
// at 46° N (spherical trigonometry, no ephemeris): a plan depends only on where they are.
#include "azt/calibration/session_planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace azt::calibration {
namespace {

constexpr double kD = 3.14159265358979323846 / 180.0;
constexpr double kLatDeg = 46.0;

struct FixedStar {
  double ra_h;
  double dec_deg;
};

/// Az/el of a star at `t_s` seconds after local sidereal time 0.
control::AzEl altaz(const FixedStar& s, double t_s) {
  const double lst_deg = t_s * 360.0 / 86164.0905;
  const double h = (lst_deg - 15.0 * s.ra_h) * kD, d = s.dec_deg * kD, p = kLatDeg * kD;
  const double el = std::asin(std::sin(p) * std::sin(d) + std::cos(p) * std::cos(d) * std::cos(h));
  const double az = std::atan2(-std::cos(d) * std::sin(h),
                               std::sin(d) * std::cos(p) - std::cos(d) * std::cos(h) * std::sin(p));
  return {std::fmod(az / kD + 360.0, 360.0), el / kD};
}

const std::vector<FixedStar> kStars{{4.7, 22.0},   {10.0, 5.0},  {23.39, 58.8},
                                    {19.99, 40.7}, {5.58, 22.0}, {12.51, 12.4}};

std::vector<PlanSource> sources(bool sun_periodic) {
  return {{"sun", 45.0, 0.53, sun_periodic}, {"moon", 20.0, 0.52, false},
          {"casa", 25.0, 0.0, false},        {"cyga", 24.0, 0.0, false},
          {"taua", 20.0, 0.0, false},        {"vira", 12.0, 0.0, false}};
}

SourcePosition sky() {
  return [](std::size_t i, double t_s) -> std::optional<control::AzEl> {
    if (i >= kStars.size()) return std::nullopt;
    return altaz(kStars[i], t_s);
  };
}

PlanSettings settings() {
  PlanSettings s;
  s.scan_s = 900.0;
  s.every_s = 0.0;
  s.min_gain = 0.001;
  s.max_scans = 1000;
  return s;
}

/// What the plan's scans cover, as plan_session counts them (halfway through each).
SkyCoverage coverage_of(const std::vector<PlannedScan>& plan, std::size_t n, double scan_s) {
  SkyCoverage c;
  for (std::size_t k = 0; k < n && k < plan.size(); ++k) {
    c.add(*sky()(plan[k].source, plan[k].t_s + 0.5 * scan_s));
  }
  return c;
}

/// The naive plan: whenever something is usable, the loudest source.
std::vector<PlannedScan> brightest_first(const SessionPlanner& rules, double end_s) {
  std::vector<PlannedScan> out;
  const double scan_s = rules.settings().scan_s;
  for (double t = 0.0; t + scan_s <= end_s;) {
    std::optional<std::size_t> pick;
    for (std::size_t i = 0; i < rules.sources().size(); ++i) {
      if (rules.usable(i, t) &&
          (!pick || rules.sources()[i].snr_db > rules.sources()[*pick].snr_db)) {
        pick = i;
      }
    }
    if (!pick) {
      t += rules.settings().wait_s;
      continue;
    }
    out.push_back({*pick, t, *sky()(*pick, t)});
    t += scan_s;
  }
  return out;
}

TEST(SessionPlanner, SpreadsTheScansBetterThanTheBrightestSourceFirst) {
  // An afternoon and evening's session of six hours, 24 scans of 15 minutes.
  const SessionPlanner planner(sources(false), sky(), SiteLimits{}, settings());
  const auto plan = plan_session(planner, 0.0, 6 * 3600.0);
  const auto naive = brightest_first(planner, 6 * 3600.0);
  const std::size_t n = std::min(plan.size(), naive.size());
  ASSERT_GE(n, 20U);
  const double planned_error = coverage_of(plan, n, 900.0).sky_error();
  const double naive_error = coverage_of(naive, n, 900.0).sky_error();
  // The same number of scans leaves the model's expected error over the sky under half (0.74
  // against 2.9 for one degree of scan noise when this was written: the Sun alone sweeps a
  // narrow band of the sky in six hours, Cas A a circle round the pole).
  EXPECT_LT(planned_error, 0.5 * naive_error) << planned_error << " vs " << naive_error;
  // And more of the sky is seen: most of the sources are used, not one or two.
  std::vector<bool> used(kStars.size(), false);
  for (std::size_t k = 0; k < n; ++k) used[plan[k].source] = true;
  EXPECT_GE(std::count(used.begin(), used.end(), true), 4);
}

TEST(SessionPlanner, NeverPlansASourceBelowTheLimits) {
  SiteLimits limits;
  limits.min_el_deg = 15.0;
  limits.max_el_deg = 75.0;
  // Trees to the south-east: nothing below 30° between 90° and 200° of azimuth.
  limits.horizon_el_deg = [](double az) { return az >= 90.0 && az <= 200.0 ? 30.0 : 0.0; };
  const SessionPlanner planner(sources(true), sky(), limits, settings());
  const auto plan = plan_session(planner, 0.0, 48 * 3600.0);
  ASSERT_GE(plan.size(), 30U);
  for (const PlannedScan& p : plan) {
    for (int k = 0; k <= 20; ++k) {
      const control::AzEl at = *sky()(p.source, p.t_s + 900.0 * k / 20.0);
      EXPECT_GE(at.el_deg, std::max(15.0, limits.horizon_el_deg(at.az_deg)) - 0.1)
          << "source " << p.source << " at " << p.t_s;
      EXPECT_LE(at.el_deg, 75.0 + 0.1);
    }
  }
}

TEST(SessionPlanner, ScansTheSunEveryIntervalWhileItIsUp) {
  PlanSettings s = settings();
  s.every_s = 1800.0;
  const SessionPlanner planner(sources(true), sky(), SiteLimits{}, s);
  const auto plan = plan_session(planner, 0.0, 24 * 3600.0);
  std::vector<double> sun;
  for (const PlannedScan& p : plan) {
    if (p.source == 0) sun.push_back(p.t_s);
  }
  ASSERT_GE(sun.size(), 8U);
  for (std::size_t k = 1; k < sun.size(); ++k) {
    const double gap = sun[k] - sun[k - 1];
    EXPECT_GE(gap, 1800.0);
    // Due every 30 minutes; a scan of another source (15 minutes) may be running then.
    if (planner.usable(0, sun[k - 1] + 2700.0)) {
      EXPECT_LE(gap, 2700.0 + 1e-6);
    }
  }
}

TEST(SessionPlanner, KeepsClearOfTheStopsAndOfOtherSources) {
  // Fixed sources: one at the north stop of a 0–360° rotator, one in the south, and two loud
  // ones a degree apart in the west.
  const std::vector<control::AzEl> at{{2.0, 40.0}, {180.0, 40.0}, {270.0, 40.0}, {271.0, 40.5}};
  const SourcePosition fixed = [at](std::size_t i, double) -> std::optional<control::AzEl> {
    return i < at.size() ? std::optional(at[i]) : std::nullopt;
  };
  const std::vector<PlanSource> four{
      {"a", 30, 0, false}, {"b", 30, 0, false}, {"c", 30, 0, false}, {"d", 30, 0, false}};
  const SessionPlanner planner(four, fixed, SiteLimits{}, settings());
  EXPECT_FALSE(planner.usable(0, 0.0));
  EXPECT_TRUE(planner.usable(1, 0.0));
  EXPECT_FALSE(planner.usable(2, 0.0));
  EXPECT_FALSE(planner.usable(3, 0.0));
  // A rotator that turns 450° has no stop at the north for this source.
  SiteLimits wide;
  wide.az_range = *control::AzimuthRange::make(-45.0, 405.0);
  EXPECT_TRUE(SessionPlanner(four, fixed, wide, settings()).usable(0, 0.0));
}

TEST(SessionPlanner, AFailedSourceWaitsAndAFaintOneIsNotOffered) {
  auto list = sources(false);
  list[5].snr_db = 5.0;  // Virgo A on a small dish
  SessionPlanner planner(list, sky(), SiteLimits{}, settings());
  double t = 0.0;
  while (!planner.usable(2, t)) t += 600.0;
  planner.scanned(2, t - 900.0, t, false);
  EXPECT_FALSE(planner.usable(2, t + 3599.0));
  for (double u = 0.0; u < 86400.0; u += 600.0) EXPECT_FALSE(planner.usable(5, u));
}

TEST(SessionPlanner, StopsAtMaxScansAndRepeatsItself) {
  PlanSettings s = settings();
  s.max_scans = 12;
  const SessionPlanner planner(sources(true), sky(), SiteLimits{}, s);
  const auto a = plan_session(planner, 0.0, 48 * 3600.0);
  const auto b = plan_session(planner, 0.0, 48 * 3600.0);
  ASSERT_EQ(a.size(), 12U);
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].source, b[k].source);
    EXPECT_EQ(a[k].t_s, b[k].t_s);
  }
  EXPECT_EQ(planner.fitted_scans(), 0U);  // the preview ran on a copy
}

}  // namespace
}  // namespace azt::calibration
