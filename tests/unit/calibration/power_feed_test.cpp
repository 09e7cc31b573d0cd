// The receiver power readings as they arrive (docs/calibration.md): freshness on injected time, the
// good, malformed and missing counters (a silence counted once), the bounded history a scan point's
// dwell window is read from, and the linear mean.
#include "azt/calibration/power_feed.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace azt::calibration {
namespace {

TEST(PowerFeed, LatestIsFreshForStaleSeconds) {
  PowerFeed feed;  // stale_s = 2
  feed.accept(10.0, -42.0);
  ASSERT_TRUE(feed.latest(10.0).has_value());
  EXPECT_EQ(*feed.latest(11.0), (PowerReading{10.0, -42.0}));
  EXPECT_TRUE(feed.latest(12.0).has_value());  // exactly stale_s old: still fresh
  EXPECT_FALSE(feed.latest(12.001).has_value());
  EXPECT_TRUE(feed.stale(12.001));
  EXPECT_FALSE(feed.stale(11.0));
  feed.accept(12.5, -40.0);
  EXPECT_EQ(feed.latest(13.0)->power_db, -40.0);
  EXPECT_FALSE(feed.latest(std::numeric_limits<double>::quiet_NaN()).has_value());
}

TEST(PowerFeed, CountsEachSilenceOnce) {
  PowerFeed feed(PowerFeedSettings{.stale_s = 1.0});
  EXPECT_TRUE(feed.stale(0.0));
  EXPECT_EQ(feed.counts().missing, 0U);        // stale() only looks
  EXPECT_FALSE(feed.latest(0.0).has_value());  // asked for one before any came: missing
  EXPECT_FALSE(feed.latest(0.1).has_value());  // the same silence
  EXPECT_EQ(feed.counts().missing, 1U);
  feed.accept(1.0, -30.0);
  for (double t = 1.0; t < 2.0; t += 0.1) EXPECT_TRUE(feed.latest(t).has_value());
  for (double t = 2.5; t < 60.0; t += 0.1) EXPECT_FALSE(feed.latest(t).has_value());
  EXPECT_EQ(feed.counts().missing, 2U);  // a minute's polling, one silence
  feed.accept(60.0, -30.0);
  feed.accept(70.0, -30.0);  // a gap nobody asked about is not a missing reading
  EXPECT_TRUE(feed.latest(70.5).has_value());
  EXPECT_EQ(feed.counts(), (PowerFeedCounts{.good = 3, .malformed = 0, .missing = 2}));
}

TEST(PowerFeed, CountsMalformedReadingsAndKeepsTheLastReason) {
  PowerFeed feed;
  EXPECT_TRUE(feed.last_malformed_reason().empty());
  EXPECT_FALSE(feed.last_malformed_s().has_value());
  feed.malformed(5.0, "power: empty line");
  feed.malformed(6.0, std::string(10000, 'x'));
  EXPECT_EQ(feed.counts().malformed, 2U);
  EXPECT_EQ(feed.last_malformed_reason().size(), kPowerFeedMaxReasonChars + 3);
  EXPECT_EQ(*feed.last_malformed_s(), 6.0);
  // A malformed line is no reading: it neither freshens the feed nor ends a silence.
  EXPECT_FALSE(feed.latest(6.0).has_value());
  // Values that are not finite are malformed, whoever parsed them.
  feed.accept(7.0, std::numeric_limits<double>::quiet_NaN());
  feed.accept(7.0, -std::numeric_limits<double>::infinity());
  feed.accept(std::numeric_limits<double>::infinity(), -3.0);
  EXPECT_EQ(feed.counts(), (PowerFeedCounts{.good = 0, .malformed = 5, .missing = 1}));
  EXPECT_EQ(feed.size(), 0U);
}

TEST(PowerFeed, ReadingsInsideADwellWindow) {
  PowerFeed feed;
  for (int i = 0; i < 20; ++i) feed.accept(0.1 * i, -40.0 - i);
  const auto window = feed.readings_between(0.5, 0.9);  // 0.5, 0.6, 0.7, 0.8 (0.9 rounds up)
  ASSERT_GE(window.size(), 4U);
  EXPECT_EQ(window.front().power_db, -45.0);
  for (const auto& r : window) EXPECT_TRUE(r.t_s >= 0.5 && r.t_s <= 0.9);
  EXPECT_EQ(feed.readings_between(1.0, 1.0).size(), 1U);  // both ends included
  EXPECT_TRUE(feed.readings_between(2.0, 1.0).empty());
  EXPECT_TRUE(feed.readings_between(5.0, 6.0).empty());
  EXPECT_EQ(feed.readings_since(1.5).size(), 5U);
  EXPECT_EQ(feed.readings_since(-1.0).size(), 20U);
  EXPECT_TRUE(feed.readings_since(std::numeric_limits<double>::quiet_NaN()).empty());
}

TEST(PowerFeed, KeepsTimeOrderWhenTheClockSteppedBack) {
  PowerFeed feed;
  feed.accept(10.0, -1.0);
  feed.accept(9.0, -2.0);  // stamped as the newest reading's time
  const auto all = feed.readings_since(0.0);
  ASSERT_EQ(all.size(), 2U);
  EXPECT_EQ(all[1], (PowerReading{10.0, -2.0}));
  EXPECT_EQ(feed.readings_between(10.0, 10.0).size(), 2U);
}

TEST(PowerFeed, HistoryIsBounded) {
  PowerFeed feed;
  for (int i = 0; i < 5000; ++i) feed.accept(i, static_cast<double>(-i % 50));
  EXPECT_EQ(feed.size(), kPowerFeedMaxHistory);
  EXPECT_EQ(feed.readings_since(0.0).front().t_s, 5000.0 - kPowerFeedMaxHistory);
  EXPECT_EQ(feed.counts().good, 5000U);

  PowerFeed small(PowerFeedSettings{.stale_s = 2.0, .history = 3});
  for (int i = 0; i < 10; ++i) small.accept(i, -1.0);
  EXPECT_EQ(small.size(), 3U);
  EXPECT_EQ(PowerFeed(PowerFeedSettings{.stale_s = 2.0, .history = 0}).settings().history, 1U);
  EXPECT_EQ(PowerFeed(PowerFeedSettings{.stale_s = 2.0, .history = 100000}).settings().history,
            kPowerFeedMaxHistory);
}

TEST(PowerFeed, NonsenseStaleTimeFallsBackToTwoSeconds) {
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(PowerFeed(PowerFeedSettings{.stale_s = bad}).settings().stale_s, 2.0) << bad;
  }
  EXPECT_EQ(PowerFeed(PowerFeedSettings{.stale_s = 0.5}).settings().stale_s, 0.5);
}

TEST(PowerFeed, MeanPowerIsAveragedInLinearUnits) {
  // −10 and −20 dB are 0.1 and 0.01: mean 0.055, −12.5963731 dB (not −15 dB).
  const std::vector<PowerReading> two{{0.0, -10.0}, {0.1, -20.0}};
  EXPECT_NEAR(*mean_power_db(two), -12.5963731, 1e-7);
  const std::vector<PowerReading> loud{{0.0, 290.0}, {0.1, 290.0}};
  EXPECT_NEAR(*mean_power_db(loud), 290.0, 1e-9);
  EXPECT_FALSE(mean_power_db({}).has_value());
  PowerFeed feed;
  feed.accept(1.0, -10.0);
  feed.accept(1.1, -20.0);
  feed.accept(5.0, 0.0);
  EXPECT_NEAR(*mean_power_db(feed.readings_between(1.0, 2.0)), -12.5963731, 1e-7);
}

}  // namespace
}  // namespace azt::calibration
