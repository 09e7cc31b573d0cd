// LeapSecondTable: the built-in IERS table, the leap-seconds.list parser and the step lookup.
//
// Dates as MJD: 1972-01-01 = 41317 and the NTP→MJD rule (MJD = NTP/86400 + 15020) are stated in
// leap-seconds.list itself; other MJDs are calendar facts cross-checked with Python's
// datetime.date (days since 1858-11-17) and, where marked, with ERFA's own test values.

#include "azt/astro/leap_seconds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using azt::astro::LeapSecondTable;

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void expect_same_steps(const LeapSecondTable& a, const LeapSecondTable& b) {
  ASSERT_EQ(a.steps().size(), b.steps().size());
  for (std::size_t i = 0; i < a.steps().size(); ++i) {
    EXPECT_EQ(a.steps()[i].mjd_utc, b.steps()[i].mjd_utc) << "step " << i;
    EXPECT_EQ(a.steps()[i].tai_minus_utc_s, b.steps()[i].tai_minus_utc_s) << "step " << i;
  }
}

// ---- builtin table --------------------------------------------------------------------------

TEST(LeapSecondBuiltin, HasAllTwentyEightStepsFrom1972To2017) {
  const auto& t = LeapSecondTable::builtin();
  ASSERT_EQ(t.steps().size(), 28u);
  // leap-seconds.list: "2272060800 10 # 1 Jan 1972" -> MJD 41317, TAI-UTC 10 s.
  EXPECT_EQ(t.steps().front().mjd_utc, 41317.0);
  EXPECT_EQ(t.steps().front().tai_minus_utc_s, 10.0);
  // IERS Bulletin C 52 (July 2016): from 2017-01-01 (MJD 57754) 0h UTC, UTC - TAI = -37 s.
  EXPECT_EQ(t.steps().back().mjd_utc, 57754.0);
  EXPECT_EQ(t.steps().back().tai_minus_utc_s, 37.0);
}

TEST(LeapSecondBuiltin, StepsAscendByOneSecond) {
  const auto& steps = LeapSecondTable::builtin().steps();
  for (std::size_t i = 1; i < steps.size(); ++i) {
    EXPECT_GT(steps[i].mjd_utc, steps[i - 1].mjd_utc) << i;
    EXPECT_EQ(steps[i].tai_minus_utc_s, steps[i - 1].tai_minus_utc_s + 1.0) << i;
  }
}

TEST(LeapSecondBuiltin, ExpiresOn2026June28) {
  // tzdata 2025b leap-seconds.list: "#@ 3991593600", "File expires on 28 June 2026" = MJD 61219.
  const auto& t = LeapSecondTable::builtin();
  EXPECT_EQ(t.expiry_mjd(), 61219.0);
  EXPECT_FALSE(t.expired_at(60748.25));  // 2025-03-14 06:00, the oracle README's instant
  EXPECT_FALSE(t.expired_at(61219.0));
  EXPECT_TRUE(t.expired_at(61219.5));
  EXPECT_TRUE(t.expired_at(70000.0));
}

TEST(LeapSecondBuiltin, LooksUpKnownDates) {
  const auto& t = LeapSecondTable::builtin();
  EXPECT_EQ(t.tai_minus_utc(41317.0), 10.0);   // 1972-01-01
  EXPECT_EQ(t.tai_minus_utc(41498.99), 10.0);  // 1972-06-30 23:45
  EXPECT_EQ(t.tai_minus_utc(41499.0), 11.0);   // 1972-07-01, the first leap second
  // ERFA t_dat: eraDat(2003, 6, 1) = 32 s (MJD 52791, ERFA t_cal2jd), eraDat(2008, 1, 17) = 33 s
  // (MJD 54482), eraDat(2017, 9, 1) = 37 s (MJD 57997).
  EXPECT_EQ(t.tai_minus_utc(52791.0), 32.0);
  EXPECT_EQ(t.tai_minus_utc(54482.0), 33.0);
  EXPECT_EQ(t.tai_minus_utc(57997.0), 37.0);
  // ERFA t_utctai: UTC 2453750.892100694 JD (MJD 53738, 2006-01-03) -> TAI - UTC = 33 s.
  EXPECT_EQ(t.tai_minus_utc(53738.392100694), 33.0);
  // Bulletin C 52: 36 s until the end of 2016-12-31, 37 s from 2017-01-01.
  EXPECT_EQ(t.tai_minus_utc(57753.999999), 36.0);
  EXPECT_EQ(t.tai_minus_utc(57754.0), 37.0);
  // After the last step the last value holds (expired_at() says whether to trust it).
  EXPECT_EQ(t.tai_minus_utc(70000.0), 37.0);
}

TEST(LeapSecondBuiltin, HasNoValueBefore1972OrForNan) {
  const auto& t = LeapSecondTable::builtin();
  EXPECT_FALSE(t.tai_minus_utc(41316.999));
  EXPECT_FALSE(t.tai_minus_utc(40587.0));  // 1970-01-01
  EXPECT_FALSE(t.tai_minus_utc(-1e9));
  EXPECT_FALSE(t.tai_minus_utc(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(t.tai_minus_utc(-std::numeric_limits<double>::infinity()));
  EXPECT_EQ(t.tai_minus_utc(std::numeric_limits<double>::infinity()), 37.0);
}

TEST(LeapSecondBuiltin, EveryStepTakesEffectAtMidnightOfItsDay) {
  const auto& steps = LeapSecondTable::builtin().steps();
  const auto& t = LeapSecondTable::builtin();
  for (std::size_t i = 0; i < steps.size(); ++i) {
    EXPECT_EQ(t.tai_minus_utc(steps[i].mjd_utc), steps[i].tai_minus_utc_s) << i;
    EXPECT_EQ(t.tai_minus_utc(steps[i].mjd_utc + 0.999), steps[i].tai_minus_utc_s) << i;
    if (i > 0) {
      EXPECT_EQ(t.tai_minus_utc(steps[i].mjd_utc - 1e-6), steps[i - 1].tai_minus_utc_s) << i;
    }
  }
}

// ---- parser on real data --------------------------------------------------------------------

TEST(LeapSecondParse, TrimmedTzdataSampleEqualsBuiltin) {
  const std::string text = read_file(std::string(AZT_TEST_DATA_DIR) + "/leap-seconds-sample.list");
  ASSERT_FALSE(text.empty()) << "missing tests/data/leap-seconds-sample.list";
  const auto parsed = LeapSecondTable::parse_ietf_list(text);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  expect_same_steps(*parsed, LeapSecondTable::builtin());
  EXPECT_EQ(parsed->expiry_mjd(), 61219.0);
}

TEST(LeapSecondParse, InstalledTzdataListMatchesBuiltinSteps) {
  const std::string path = "/usr/share/zoneinfo/leap-seconds.list";
  const std::string text = read_file(path);
  if (text.empty()) GTEST_SKIP() << path << " is not installed";
  const auto parsed = LeapSecondTable::parse_ietf_list(text);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  // A failure here means IERS announced a leap second: update builtin() from this file.
  expect_same_steps(*parsed, LeapSecondTable::builtin());
  // A newer tzdata may carry a later expiry, never an earlier one.
  EXPECT_GE(parsed->expiry_mjd(), LeapSecondTable::builtin().expiry_mjd());
}

// ---- parser: small texts --------------------------------------------------------------------

constexpr const char* kTwoSteps =
    "# comment\n"
    "#$\t3960835200\n"
    "#@\t3991593600\n"
    "2272060800\t10\t# 1 Jan 1972\n"
    "2287785600      11      # 1 Jul 1972\n";

TEST(LeapSecondParse, ReadsAMinimalList) {
  const auto parsed = LeapSecondTable::parse_ietf_list(kTwoSteps);
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  ASSERT_EQ(parsed->steps().size(), 2u);
  EXPECT_EQ(parsed->steps()[1].mjd_utc, 41499.0);  // 1 Jul 1972
  EXPECT_EQ(parsed->steps()[1].tai_minus_utc_s, 11.0);
  EXPECT_EQ(parsed->expiry_mjd(), 61219.0);
  EXPECT_EQ(parsed->tai_minus_utc(45000.0), 11.0);
  EXPECT_FALSE(parsed->tai_minus_utc(41316.5));
}

TEST(LeapSecondParse, AcceptsCrlfBlankLinesAndNoFinalNewline) {
  const auto parsed = LeapSecondTable::parse_ietf_list(
      "\r\n#@ 3991593600\r\n\r\n   \n2272060800 10\r\n2287785600 11 #x");
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  EXPECT_EQ(parsed->steps().size(), 2u);
}

TEST(LeapSecondParse, AcceptsANegativeLeapSecond) {
  // Never used so far, but allowed by the IERS rules: TAI - UTC would drop by one second.
  const auto parsed =
      LeapSecondTable::parse_ietf_list("#@ 3991593600\n3692217600 37\n3960835200 36\n");
  ASSERT_TRUE(parsed.ok()) << parsed.error().message;
  // NTP 3960835200 = MJD 60863 (2025-07-01).
  EXPECT_EQ(parsed->tai_minus_utc(60862.5), 37.0);
  EXPECT_EQ(parsed->tai_minus_utc(60863.0), 36.0);
}

void expect_error(std::string_view text, const std::string& line, const std::string& words) {
  const auto parsed = LeapSecondTable::parse_ietf_list(text);
  ASSERT_FALSE(parsed.ok()) << text;
  const std::string& msg = parsed.error().message;
  EXPECT_TRUE(contains(msg, line)) << msg;
  EXPECT_TRUE(contains(msg, words)) << msg;
}

TEST(LeapSecondParse, RejectsStepsOutOfOrder) {
  expect_error("#@ 3991593600\n2287785600 11\n2272060800 10\n", "line 3", "out of order");
  expect_error("#@ 3991593600\n2272060800 10\n2272060800 11\n", "line 3", "out of order");
}

TEST(LeapSecondParse, RejectsNonIntegerNumbers) {
  expect_error("#@ 3991593600\n2272060800 10.5\n", "line 2", "TAI-UTC \"10.5\"");
  expect_error("#@ 3991593600\n2272060800.0 10\n", "line 2", "\"2272060800.0\"");
  expect_error("#@ 3991593600\n227206080x 10\n", "line 2", "\"227206080x\"");
  expect_error("#@ 3991593600\n-2272060800 10\n", "line 2", "\"-2272060800\"");
  expect_error("#@ 3991593600\n2272060800 ten\n", "line 2", "\"ten\"");
  expect_error("#@ 3991593600\n2272060800 99999999999999999999\n", "line 2", "TAI-UTC");
  expect_error("#@ 39915936OO\n2272060800 10\n", "line 1", "\"39915936OO\"");
}

TEST(LeapSecondParse, RejectsWrongFieldCounts) {
  expect_error("#@ 3991593600\n2272060800\n", "line 2", "NTP_SECONDS TAI-UTC");
  expect_error("#@ 3991593600\n2272060800 10 1972\n", "line 2", "NTP_SECONDS TAI-UTC");
  expect_error("#@\n2272060800 10\n", "line 1", "#@ NTP_SECONDS");
  expect_error("#@ 3991593600 1\n2272060800 10\n", "line 1", "#@ NTP_SECONDS");
}

TEST(LeapSecondParse, RejectsOffsetsThatDoNotChangeByOneSecond) {
  expect_error("#@ 3991593600\n2272060800 10\n2287785600 10\n", "line 3", "changes by 0 s");
  expect_error("#@ 3991593600\n2272060800 10\n2287785600 12\n", "line 3", "changes by 2 s");
  // The extreme ints must be reported, not overflow (UBSan would catch a 32-bit subtraction).
  expect_error("#@ 3991593600\n2272060800 -2147483648\n2287785600 2147483647\n", "line 3",
               "changes by 4294967295 s");
}

TEST(LeapSecondParse, RejectsTimestampsOffMidnightOrBefore1972) {
  expect_error("#@ 3991593600\n2272060801 10\n", "line 2", "00:00 UTC");
  // 2272060800 - 86400 = 1971-12-31, before leap-second UTC existed.
  expect_error("#@ 3991593600\n2271974400 10\n", "line 2", "before 1972-01-01");
}

TEST(LeapSecondParse, RejectsMissingOrBadExpiry) {
  const auto no_expiry = LeapSecondTable::parse_ietf_list("2272060800 10\n2287785600 11\n");
  ASSERT_FALSE(no_expiry.ok());
  EXPECT_TRUE(contains(no_expiry.error().message, "no expiry line")) << no_expiry.error().message;
  expect_error("#@ 3991593600\n#@ 3991593600\n2272060800 10\n", "line 2", "second expiry line");
  // Expiry 1972-07-01 while the last step is on that very day.
  expect_error("#@ 2287785600\n2272060800 10\n2287785600 11\n", "line 1", "not after the last");
}

TEST(LeapSecondParse, RejectsAListWithoutData) {
  for (const char* text : {"", "\n\n", "# only comments\n#@ 3991593600\n"}) {
    const auto parsed = LeapSecondTable::parse_ietf_list(text);
    ASSERT_FALSE(parsed.ok()) << text;
    EXPECT_TRUE(contains(parsed.error().message, "no data lines")) << parsed.error().message;
  }
}

// ---- seeded random lists --------------------------------------------------------------------

// Property: any well-formed list (random dates, random ±1 s steps, random blanks and comments)
// parses to exactly its steps, and a lookup anywhere inside step i's interval returns step i.
TEST(LeapSecondParse, RandomWellFormedListsRoundTrip) {
  std::mt19937_64 rng(0x1eab5ec0);
  std::uniform_int_distribution<int> gap_days(1, 2000);
  std::uniform_int_distribution<int> count(1, 40);
  std::bernoulli_distribution coin(0.5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const char* blanks[] = {" ", "\t", "   ", "\t \t"};
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::pair<long long, int>> steps;  // (mjd, offset)
    long long mjd = 41317 + gap_days(rng) - 1;
    int offset = 10 + count(rng);
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
      steps.emplace_back(mjd, offset);
      mjd += gap_days(rng);
      offset += coin(rng) ? 1 : -1;
    }
    const long long expiry_mjd = mjd + gap_days(rng);
    std::string text = "# random list " + std::to_string(trial) + "\n";
    const auto ntp = [](long long day) { return std::to_string((day - 15020) * 86400); };
    text += "#@" + std::string(blanks[trial % 4]) + ntp(expiry_mjd) + "\n";
    for (const auto& [day, off] : steps) {
      text += ntp(day) + blanks[rng() % 4] + std::to_string(off);
      text += coin(rng) ? "\t# note\n" : "\n";
      if (coin(rng)) text += "#\n";
    }
    const auto parsed = LeapSecondTable::parse_ietf_list(text);
    ASSERT_TRUE(parsed.ok()) << parsed.error().message << "\n" << text;
    ASSERT_EQ(parsed->steps().size(), steps.size());
    EXPECT_EQ(parsed->expiry_mjd(), static_cast<double>(expiry_mjd));
    for (std::size_t i = 0; i < steps.size(); ++i) {
      EXPECT_EQ(parsed->steps()[i].mjd_utc, static_cast<double>(steps[i].first));
      EXPECT_EQ(parsed->steps()[i].tai_minus_utc_s, static_cast<double>(steps[i].second));
      const double end = i + 1 < steps.size() ? static_cast<double>(steps[i + 1].first)
                                              : static_cast<double>(expiry_mjd);
      const double start = static_cast<double>(steps[i].first);
      const double q = start + (end - start) * unit(rng) * 0.999999;
      EXPECT_EQ(parsed->tai_minus_utc(q), static_cast<double>(steps[i].second)) << q;
    }
    EXPECT_FALSE(parsed->tai_minus_utc(static_cast<double>(steps.front().first) - 0.5));
  }
}

}  // namespace
