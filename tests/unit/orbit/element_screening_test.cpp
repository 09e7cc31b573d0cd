// Every refusal of a downloaded element set, and the merge by NORAD number
// (azt/orbit/element_screening.hpp). Times are fixed instants: nothing reads the clock.
#include "azt/orbit/element_screening.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace azt::orbit {
namespace {

constexpr double kNowUnixS = 1709296200.0;  // 2024-03-01 12:30 UTC
constexpr double kDay = 86400.0;

/// A set of NORAD number `norad` whose epoch is `age_days` before kNowUnixS.
Elements aged(const std::string& norad, double age_days, const std::string& name = "") {
  Elements e;
  e.catalog = norad;
  e.name = name.empty() ? "SAT " + norad : name;
  const double jd = (kNowUnixS - age_days * kDay) / kDay + 2440587.5;
  e.epoch_jd = std::floor(jd - 0.5) + 0.5;
  e.epoch_jd_frac = jd - e.epoch_jd;
  return e;
}

std::vector<Elements> many(int count, double age_days) {
  std::vector<Elements> out;
  for (int i = 0; i < count; ++i) out.push_back(aged(std::to_string(10000 + i), age_days));
  return out;
}

TEST(ElementScreening, AGoodFirstDownloadIsAccepted) {
  const ElementDownload d{many(20, 1.0), {}};
  EXPECT_TRUE(screen_download(d, {}, kNowUnixS).accepted());
}

TEST(ElementScreening, AnEmptyDownloadIsRefused) {
  const Screening s = screen_download(ElementDownload{}, {}, kNowUnixS);
  EXPECT_EQ(s.refusal, "no element sets in it");
}

TEST(ElementScreening, OneEntryThatDoesNotParseRefusesTheWholeDownload) {
  ElementDownload d{many(20, 1.0), {"x.tle: NOAA 19: line 2: checksum 7, expected 3", "x: two"}};
  const Screening s = screen_download(d, {}, kNowUnixS);
  EXPECT_FALSE(s.accepted());
  EXPECT_NE(s.refusal.find("does not parse: x.tle: NOAA 19: line 2: checksum"), std::string::npos);
  EXPECT_NE(s.refusal.find("(and 1 more)"), std::string::npos) << s.refusal;
}

TEST(ElementScreening, AnEpochDaysAheadOfTheClockIsRefused) {
  ElementDownload d{many(5, 1.0), {}};
  d.sets.push_back(aged("25544", -4.0, "ISS"));
  const Screening s = screen_download(d, {}, kNowUnixS);
  EXPECT_NE(s.refusal.find("implausible epoch: ISS"), std::string::npos) << s.refusal;
  EXPECT_NE(s.refusal.find("4 days ahead"), std::string::npos) << s.refusal;
  // A day ahead is what supplemental elements may hold.
  d.sets.back() = aged("25544", -1.0, "ISS");
  EXPECT_TRUE(screen_download(d, {}, kNowUnixS).accepted());
}

TEST(ElementScreening, AnAbsurdlyOldEpochIsRefused) {
  ElementDownload d{many(5, 1.0), {}};
  d.sets.push_back(aged("00005", 20000.0, "VANGUARD 1"));
  const Screening s = screen_download(d, {}, kNowUnixS);
  EXPECT_NE(s.refusal.find("implausible epoch: VANGUARD 1"), std::string::npos) << s.refusal;
  EXPECT_NE(s.refusal.find("days old"), std::string::npos) << s.refusal;
}

TEST(ElementScreening, UnderATenthOfThePreviousCountIsSuspicious) {
  const std::vector<Elements> previous = many(100, 2.0);
  const Screening s = screen_download(ElementDownload{many(9, 1.0), {}}, previous, kNowUnixS);
  EXPECT_EQ(s.refusal, "suspicious: 9 element sets where the last download had 100 (under 10 %)");
  EXPECT_TRUE(screen_download(ElementDownload{many(10, 1.0), {}}, previous, kNowUnixS).accepted());
}

TEST(ElementScreening, ASatelliteGoingBackInEpochRefusesTheDownload) {
  const std::vector<Elements> previous{aged("25544", 1.0, "ISS"), aged("7530", 1.0)};
  ElementDownload d{{aged("25544", 3.0, "ISS"), aged("07530", 0.5)}, {}};
  const Screening s = screen_download(d, previous, kNowUnixS);
  EXPECT_NE(s.refusal.find("went back in time: ISS has epoch 2024-02-27"), std::string::npos)
      << s.refusal;
  // The same epoch again (CelesTrak's file between two updates) is no step back; zero-padding
  // does not make another satellite.
  d.sets[0] = previous[0];
  EXPECT_TRUE(screen_download(d, previous, kNowUnixS).accepted());
  d.sets[1] = aged("07530", 2.0);
  EXPECT_NE(screen_download(d, previous, kNowUnixS).refusal.find("SAT 07530"), std::string::npos);
}

TEST(ElementScreening, ANewSatelliteOrOneDroppedIsNoStepBack) {
  const std::vector<Elements> previous{aged("25544", 1.0), aged("43017", 1.0)};
  const ElementDownload d{{aged("25544", 0.5), aged("99999", 0.5)}, {}};
  EXPECT_TRUE(screen_download(d, previous, kNowUnixS).accepted());
}

TEST(ElementMerge, TheNewestEpochWinsPerNoradNumberInFirstSeenOrder) {
  const std::vector<Elements> a{aged("25544", 2.0, "ISS A"), aged("43017", 1.0, "AO-91 A")};
  const std::vector<Elements> b{aged("43017", 3.0, "AO-91 B"), aged("025544", 0.5, "ISS B"),
                                aged("27607", 1.0, "SO-50")};
  const std::vector<Elements> merged = merge_newest({&a, nullptr, &b});
  ASSERT_EQ(merged.size(), 3U);
  EXPECT_EQ(merged[0].name, "ISS B");
  EXPECT_EQ(merged[1].name, "AO-91 A");
  EXPECT_EQ(merged[2].name, "SO-50");
}

TEST(ElementMerge, ATieGoesToTheEarlierSource) {
  const std::vector<Elements> a{aged("25544", 1.0, "first")};
  const std::vector<Elements> b{aged("25544", 1.0, "second")};
  EXPECT_EQ(merge_newest({&a, &b}).front().name, "first");
}

TEST(ElementEpoch, UnixSecondsOfAnEpoch) {
  EXPECT_NEAR(epoch_unix_s(aged("1", 0.25)), kNowUnixS - 0.25 * kDay, 1e-3);
  EXPECT_EQ(norad_key("00005"), "5");
  EXPECT_EQ(norad_key("0000"), "0");
}

}  // namespace
}  // namespace azt::orbit
