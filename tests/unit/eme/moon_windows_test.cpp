// Common Moon windows (docs/eme.md): the edges are where the limit is crossed, a window under
// way at the start begins there, limits and masks the Moon never clears give none, and the best
// minute lies inside its window. astropy checks the times (moon_windows_oracle.py).
#include "azt/eme/moon_windows.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/sky.hpp"

namespace azt::eme {
namespace {

constexpr double kFrom = 1740787200.0;  // 2025-03-01 00:00 UTC
const astro::Observer kFn06{46.1875, -79.375, 0.0};
const astro::Observer kJo62{52.52, 14.96, 0.0};

double moon_el(double unix_s, const astro::Observer& where) {
  static const astro::ErfaEphemeris eph;
  const auto t = astro::make_time_scales(astro::UtcInstant::from_unix_seconds(unix_s), 0.0,
                                         astro::LeapSecondTable::builtin());
  const auto epoch = astro::make_epoch(eph, *t);
  return astro::observe_moon(eph, *epoch, astro::make_station(*epoch, where))->el_geometric_deg;
}

Result<std::vector<MoonWindow>> windows(const MoonWindowSettings& s) {
  static const astro::ErfaEphemeris eph;
  return moon_windows(eph, kFn06, kJo62, s, astro::LeapSecondTable::builtin());
}

TEST(MoonWindows, EdgesAreWhereALimitIsCrossed) {
  MoonWindowSettings s;
  s.from_unix_s = kFrom;
  s.days = 5.0;
  s.min_el_deg = 5.0;
  s.dx_min_el_deg = 10.0;
  const auto w = windows(s);
  ASSERT_TRUE(w) << w.error().message;
  ASSERT_GE(w->size(), 4U);
  for (const auto& x : *w) {
    EXPECT_LT(x.start_unix_s, x.end_unix_s);
    // At each edge one station is at its limit (the Moon moves 0.25° a minute at most: 1 s of
    // edge error is 0.005°), and both are above it a minute inside.
    const double at_start =
        std::min(moon_el(x.start_unix_s, kFn06) - 5.0, moon_el(x.start_unix_s, kJo62) - 10.0);
    const double at_end =
        std::min(moon_el(x.end_unix_s, kFn06) - 5.0, moon_el(x.end_unix_s, kJo62) - 10.0);
    EXPECT_NEAR(at_start, 0.0, 0.01);
    EXPECT_NEAR(at_end, 0.0, 0.01);
    EXPECT_GT(moon_el(x.start_unix_s + 60.0, kFn06), 5.0);
    EXPECT_GT(moon_el(x.start_unix_s + 60.0, kJo62), 10.0);
    EXPECT_GE(x.best_unix_s, x.start_unix_s);
    EXPECT_LE(x.best_unix_s, x.end_unix_s);
    EXPECT_NEAR(x.el_deg, moon_el(x.best_unix_s, kFn06), 1e-9);
  }
}

TEST(MoonWindows, AWindowUnderWayStartsAtTheStart) {
  MoonWindowSettings s;
  s.days = 1.0;
  // Start inside the first window found from kFrom.
  s.from_unix_s = kFrom;
  const auto first = windows(s);
  ASSERT_TRUE(first && !first->empty());
  s.from_unix_s = 0.5 * (first->front().start_unix_s + first->front().end_unix_s);
  const auto w = windows(s);
  ASSERT_TRUE(w && !w->empty());
  EXPECT_DOUBLE_EQ(w->front().start_unix_s, s.from_unix_s);
  EXPECT_NEAR(w->front().end_unix_s, first->front().end_unix_s, 1.0);
}

TEST(MoonWindows, LimitsTheMoonNeverClearsGiveNone) {
  MoonWindowSettings s;
  s.from_unix_s = kFrom;
  s.days = 30.0;
  s.min_el_deg = 80.0;  // at 46° N the Moon culminates at 72° at most
  EXPECT_TRUE(windows(s)->empty());
  s.min_el_deg = 0.0;
  s.dx_mask = orbit::HorizonMask::flat(75.0);
  EXPECT_TRUE(windows(s)->empty());
}

// A fixed-elevation array (12° ± 2°, a 4° beam: narrower than the 10-minute step's 2.5°
// of Moon climb could skip): the windows are where both stations see the Moon and it is inside
// the band, checked against an independent 20 s scan of the same conditions.
TEST(MoonWindows, AFixedArraysWindowsAreTheMoonInsideItsBeam) {
  MoonWindowSettings s;
  s.from_unix_s = kFrom;
  s.days = 4.0;
  s = in_fixed_beam(s, 12.0, 4.0);
  ASSERT_EQ(s.min_el_deg, 10.0);
  ASSERT_EQ(s.max_el_deg, 14.0);
  const auto w = windows(s);
  ASSERT_TRUE(w) << w.error().message;
  const auto inside = [](double t) {
    const double el = moon_el(t, kFn06);
    return el >= 10.0 && el <= 14.0 && moon_el(t, kJo62) >= 0.0;
  };
  std::vector<std::pair<double, double>> scanned;  // the scan's own windows, to 20 s
  constexpr double kScanS = 20.0;
  for (int i = 0; i * kScanS < s.days * 86400.0; ++i) {
    const double t = s.from_unix_s + i * kScanS;
    const bool in = inside(t);
    if (in && (scanned.empty() || scanned.back().second < t - kScanS)) scanned.emplace_back(t, t);
    if (in) scanned.back().second = t;
  }
  ASSERT_GE(scanned.size(), 2U);  // the band is crossed at moonrise or moonset most days
  ASSERT_EQ(w->size(), scanned.size());
  for (std::size_t i = 0; i < w->size(); ++i) {
    EXPECT_NEAR(w->at(i).start_unix_s, scanned[i].first, kScanS);
    EXPECT_NEAR(w->at(i).end_unix_s, scanned[i].second, kScanS);
    EXPECT_GE(w->at(i).el_deg, 10.0);
    EXPECT_LE(w->at(i).el_deg, 14.0);
  }
}

}  // namespace
}  // namespace azt::eme
