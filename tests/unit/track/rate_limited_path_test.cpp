// The reachable sets and the path read back through them (docs/satellites.md), on cases small
// enough to check by hand.
#include "azt/track/rate_limited_path.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace azt::track {
namespace {

TEST(Spans, WideningMergesAndIntersectingKeepsWhatBothHold) {
  const Spans s{{0.0, 1.0}, {3.0, 4.0}};
  const Spans w = widened(s, 1.0);
  ASSERT_EQ(w.size(), 1U) << "1 and 3 meet once widened by 1";
  EXPECT_DOUBLE_EQ(w[0].lo, -1.0);
  EXPECT_DOUBLE_EQ(w[0].hi, 5.0);
  const Spans both = intersection(s, Spans{{0.5, 3.5}});
  ASSERT_EQ(both.size(), 2U);
  EXPECT_DOUBLE_EQ(both[0].lo, 0.5);
  EXPECT_DOUBLE_EQ(both[1].hi, 3.5);
  EXPECT_TRUE(intersection(s, Spans{{1.5, 2.5}}).empty());
  EXPECT_DOUBLE_EQ(gap(s, Spans{{6.0, 7.0}}), 2.0);
  EXPECT_DOUBLE_EQ(gap(s, Spans{{0.5, 7.0}}), 0.0);
  EXPECT_TRUE(std::isinf(gap(s, Spans{})));
}

TEST(Reachability, AJumpFasterThanTheRateIsUnreachableAndASlowOneIsNot) {
  const std::vector<double> t{0.0, 1.0, 2.0};
  const std::vector<Spans> allowed{{{0.0, 0.0}}, {{0.0, 10.0}}, {{10.0, 10.0}}};
  EXPECT_TRUE(reachable_forward(t, allowed, 4.0, {{-100.0, 100.0}}).back().empty())
      << "10 in 2 s at 4/s";
  const auto reach = reachable_forward(t, allowed, 5.0, {{-100.0, 100.0}});
  ASSERT_FALSE(reach.back().empty());
  EXPECT_DOUBLE_EQ(reach[1].front().hi, 5.0);
  const auto back = reachable_backward(t, allowed, 5.0);
  EXPECT_DOUBLE_EQ(back[1].front().lo, 5.0) << "only 5 at t=1 reaches 10 at t=2";
}

TEST(Reachability, ThePathReadBackStaysWithinTheRateAndPrefersWhatItIsAsked) {
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0};
  const std::vector<Spans> allowed{
      {{0.0, 2.0}, {8.0, 9.0}}, {{0.0, 20.0}}, {{0.0, 20.0}}, {{12.0, 13.0}}};
  const auto reach = reachable_forward(t, allowed, 3.5, {{-100.0, 100.0}});
  ASSERT_FALSE(reach.back().empty());
  // Ask for 0 everywhere: the path must still end in 12–13 and start where 4/s gets there.
  const auto path = path_through(t, reach, 3.5, [](std::size_t, Span s, std::optional<double>) {
    return std::pair{std::clamp(0.0, s.lo, s.hi), std::fabs(std::clamp(0.0, s.lo, s.hi))};
  });
  ASSERT_EQ(path.size(), 4U);
  EXPECT_DOUBLE_EQ(path[3], 12.0);
  EXPECT_NEAR(path[0], 1.5, 1e-6) << "the lowest start 12 can be reached from at 3.5/s";
  for (std::size_t i = 1; i < path.size(); ++i)
    EXPECT_LE(std::fabs(path[i] - path[i - 1]), 3.5 + 1e-6);
}

}  // namespace
}  // namespace azt::track
