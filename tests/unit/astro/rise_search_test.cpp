// The rise search (rise_search.hpp) against a sky whose crossings are known in closed form: an
// "elevation" of 30° sin(2π t / 1 day) − 10°, which rises through 0° at t = asin(1/3) / 2π days.
#include "azt/astro/rise_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace azt::astro {
namespace {

constexpr double kDay = 86400.0;

double elevation_deg(double t) { return 30.0 * std::sin(2.0 * std::numbers::pi * t / kDay) - 10.0; }

ReachableAt above(double limit_deg, int* calls = nullptr) {
  return [limit_deg, calls](double t) -> Result<bool> {
    if (calls != nullptr) ++*calls;
    return elevation_deg(t) >= limit_deg;
  };
}

TEST(RiseSearch, FindsTheRiseToTheTolerance) {
  const double rise = std::asin(1.0 / 3.0) / (2.0 * std::numbers::pi) * kDay;  // 4707.5 s
  // From the set (t = half a day less the rise) through the night to the next day's rise.
  const double set = 0.5 * kDay - rise;
  auto t = next_reachable(above(0.0), set + 60.0);
  ASSERT_TRUE(t);
  ASSERT_TRUE(t->has_value());
  EXPECT_NEAR(**t, kDay + rise, 1.0);
  EXPECT_GE(**t, kDay + rise - 1e-6);  // never before it is reachable
}

TEST(RiseSearch, ReachableNowIsNow) {
  auto t = next_reachable(above(0.0), 0.25 * kDay);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->value(), 0.25 * kDay);
}

TEST(RiseSearch, NeverWithinTheSpanIsNone) {
  int calls = 0;
  auto t = next_reachable(above(25.0, &calls), 0.0);  // the peak is 20°
  ASSERT_TRUE(t);
  EXPECT_FALSE(t->has_value());
  EXPECT_EQ(calls, 1 + static_cast<int>(2.0 * kDay / 300.0));  // every step, no more
}

TEST(RiseSearch, TheSkysErrorIsReturned) {
  auto t =
      next_reachable([](double) -> Result<bool> { return fail("outside the ephemeris"); }, 0.0);
  ASSERT_FALSE(t);
  EXPECT_EQ(t.error().message, "outside the ephemeris");
}

TEST(RiseSearch, AStepThatIsNotPositiveIsRefused) {
  EXPECT_FALSE(next_reachable(above(0.0), 0.0, RiseSearch{0.0, kDay, 1.0}));
  EXPECT_FALSE(next_reachable(above(0.0), 0.0, RiseSearch{std::nan(""), kDay, 1.0}));
}

}  // namespace
}  // namespace azt::astro
