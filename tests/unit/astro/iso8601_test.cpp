// parse_iso8601_utc / format_iso8601_utc.
//
// Sources of the worked values:
//  - Oracle README (/work/shared/oracles/README.md): 2025-03-14 06:00:00 UTC is JD 2460748.75.
//  - ERFA t_jd2cal: JD 2400000.5 + 50123.9999 is 1996-02-10 with day fraction 0.9999
//    (= 86391.36 s = 23:59:51.360).
//  - Well-known Unix times: 1e9 s = 2001-09-09T01:46:40Z, 1234567890 s = 2009-02-13T23:31:30Z.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "azt/astro/time_scales.hpp"
#include "test_support.hpp"

namespace {

using azt::astro::format_iso8601_utc;
using azt::astro::parse_iso8601_utc;
using azt::astro::UtcInstant;

using azt::test::calendar;
using azt::test::contains;

double seconds_between(const UtcInstant& a, const UtcInstant& b) {
  return ((b.jd.jd1 - a.jd.jd1) + (b.jd.jd2 - a.jd.jd2)) * 86400.0;
}

// ---- parsing --------------------------------------------------------------------------------

TEST(ParseIso8601, OracleInstant) {
  const auto t = parse_iso8601_utc("2025-03-14T06:00:00Z");
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_EQ(t->jd.jd1, 2460748.5);
  EXPECT_EQ(t->jd.jd2, 0.25);
}

TEST(ParseIso8601, AcceptsEveryDocumentedSpelling) {
  for (const char* text :
       {"2025-03-14T06:00Z", "2025-03-14 06:00Z", "2025-03-14T06:00:00Z", "2025-03-14 06:00:00Z",
        "2025-03-14T06:00:00.000Z", "2025-03-14T06:00:00.0Z", "2025-03-14T06:00:00+00:00",
        "2025-03-14T06:00:00+0000", "2025-03-14T06:00+00:00",
        "2025-03-14 06:00:00.000000000+0000"}) {
    const auto t = parse_iso8601_utc(text);
    ASSERT_TRUE(t.ok()) << text << ": " << t.error().message;
    EXPECT_EQ(t->jd.jd1, 2460748.5) << text;
    EXPECT_EQ(t->jd.jd2, 0.25) << text;
  }
}

TEST(ParseIso8601, ReadsFractionalSeconds) {
  const auto t = parse_iso8601_utc("2025-03-14T06:00:07.123456Z");
  ASSERT_TRUE(t.ok()) << t.error().message;
  EXPECT_NEAR(t->jd.jd2 * 86400.0, 21607.123456, 1e-9);
  const auto u = parse_iso8601_utc("2025-03-14T06:00:07.5Z");
  ASSERT_TRUE(u.ok());
  EXPECT_NEAR(u->jd.jd2 * 86400.0, 21607.5, 1e-9);
}

TEST(ParseIso8601, KeepsAFractionThatRoundsTo60InsideTheMinute) {
  // As a double, 59.99999999999999999 is 60.0; it must still be read as 23:59:59.999..., not
  // rejected as second 60. (On a 86400 s day the last representable step is ~15 ps, so the
  // instant may coincide with the next midnight; it must not land after it.)
  const auto t = parse_iso8601_utc("2024-12-31T23:59:59.99999999999999999Z");
  ASSERT_TRUE(t.ok()) << t.error().message;
  const auto midnight = calendar(2025, 1, 1, 0, 0, 0.0);
  const double gap_s = seconds_between(*t, midnight);
  EXPECT_GE(gap_s, 0.0);
  EXPECT_LT(gap_s, 1e-9);
  EXPECT_EQ(format_iso8601_utc(*t), "2025-01-01T00:00:00.000Z");
  // Elsewhere in the day the same text stays at or just before the next minute.
  const auto noon = parse_iso8601_utc("2025-03-14T06:00:59.99999999999999999Z");
  ASSERT_TRUE(noon.ok()) << noon.error().message;
  const double to_next_minute_s = seconds_between(*noon, calendar(2025, 3, 14, 6, 1, 0.0));
  EXPECT_GE(to_next_minute_s, 0.0);
  EXPECT_LT(to_next_minute_s, 1e-9);
}

void expect_parse_error(const std::string& text, const std::string& words) {
  const auto t = parse_iso8601_utc(text);
  ASSERT_FALSE(t.ok()) << "accepted: " << text;
  const std::string& msg = t.error().message;
  EXPECT_TRUE(contains(msg, words)) << msg;
  EXPECT_TRUE(contains(msg, "\"" + text + "\"")) << "message must quote the input: " << msg;
}

TEST(ParseIso8601, RejectsAMissingZone) {
  expect_parse_error("2025-03-14T06:00:00", "no time zone");
  expect_parse_error("2025-03-14T06:00", "no time zone");
  expect_parse_error("2025-03-14T06:00:00.250", "no time zone");
}

TEST(ParseIso8601, RejectsOtherOffsets) {
  expect_parse_error("2025-03-14T06:00:00+01:00", "is not UTC");
  expect_parse_error("2025-03-14T06:00:00-05:00", "is not UTC");
  expect_parse_error("2025-03-14T06:00:00-00:00", "is not UTC");  // RFC 3339: unknown offset
  expect_parse_error("2025-03-14T06:00:00+00", "is not UTC");
  expect_parse_error("2025-03-14T06:00:00+00:00:00", "is not UTC");
}

TEST(ParseIso8601, RejectsJunk) {
  expect_parse_error("", "4-digit year");
  expect_parse_error("2025-03-14", "'T' or ' '");
  expect_parse_error("25-03-14T06:00Z", "4-digit year");
  expect_parse_error("2025/03/14T06:00Z", "4-digit year");
  expect_parse_error("2025-3-14T06:00Z", "2-digit month");
  expect_parse_error("2025-03-4T06:00Z", "2-digit day");
  expect_parse_error("2025-03-14_06:00Z", "'T' or ' '");
  expect_parse_error("2025-03-14t06:00Z", "'T' or ' '");
  expect_parse_error("2025-03-14T6:00Z", "2-digit hour");
  expect_parse_error("2025-03-14T06Z", "2-digit hour");
  expect_parse_error("2025-03-14T06:0Z", "2-digit minutes");
  expect_parse_error("2025-03-14T06:00:5Z", "2-digit seconds");
  expect_parse_error("2025-03-14T06:00:00.Z", "digits after the decimal point");
  expect_parse_error("2025-03-14T06:00:00,5Z", "unexpected");
  expect_parse_error("2025-03-14T06:00:00z", "unexpected");
  expect_parse_error("2025-03-14T06:00:00Z ", "unexpected");
  expect_parse_error("2025-03-14T06:00:00ZZ", "unexpected");
  expect_parse_error(" 2025-03-14T06:00Z", "4-digit year");
  expect_parse_error("+2025-03-14T06:00Z", "4-digit year");
  expect_parse_error("2025-03-14T06:00:00.5e3Z", "unexpected");
}

TEST(ParseIso8601, RejectsImpossibleFieldsWithTheCalendarReason) {
  expect_parse_error("2025-13-01T00:00Z", "month 13");
  expect_parse_error("2025-02-29T00:00Z", "day 29");
  expect_parse_error("2025-03-14T24:00Z", "hour 24");
  expect_parse_error("2025-03-14T06:60Z", "minute 60");
  expect_parse_error("2025-03-14T06:00:61Z", "second 61");
  expect_parse_error("1899-12-31T00:00Z", "year 1899");
}

TEST(ParseIso8601, SaysLeapSecondInstantsAreNotSupported) {
  // 2016-12-31T23:59:60Z existed (Bulletin C 52), but a uniform 86400 s day cannot hold it.
  expect_parse_error("2016-12-31T23:59:60Z", "leap-second instants (23:59:60) are not supported");
  expect_parse_error("2016-12-31T23:59:60.5Z", "not supported");
}

TEST(ParseIso8601, TruncatesVeryLongInputInTheMessage) {
  const std::string junk(500, 'x');
  const auto t = parse_iso8601_utc(junk);
  ASSERT_FALSE(t.ok());
  EXPECT_LT(t.error().message.size(), 200u);
  EXPECT_TRUE(contains(t.error().message, "xxxx...\"")) << t.error().message;
}

// ---- formatting -----------------------------------------------------------------------------

TEST(FormatIso8601, OracleInstant) {
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 14, 6, 0, 0.0)), "2025-03-14T06:00:00.000Z");
}

TEST(FormatIso8601, ErfaJd2calExample) {
  EXPECT_EQ(format_iso8601_utc(UtcInstant{{2400000.5, 50123.9999}}), "1996-02-10T23:59:51.360Z");
}

TEST(FormatIso8601, WellKnownUnixTimes) {
  EXPECT_EQ(format_iso8601_utc(UtcInstant::from_unix_seconds(0.0)), "1970-01-01T00:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(UtcInstant::from_unix_seconds(1e9)), "2001-09-09T01:46:40.000Z");
  EXPECT_EQ(format_iso8601_utc(UtcInstant::from_unix_seconds(1234567890.0)),
            "2009-02-13T23:31:30.000Z");
  EXPECT_EQ(format_iso8601_utc(UtcInstant::from_unix_seconds(-1.0)), "1969-12-31T23:59:59.000Z");
  EXPECT_EQ(format_iso8601_utc(UtcInstant::from_unix_seconds(1741932000.25)),
            "2025-03-14T06:00:00.250Z");
}

TEST(FormatIso8601, AcceptsAnyTwoPartSplit) {
  // The same instant, 2025-03-14T06:00Z, split three ways.
  EXPECT_EQ(format_iso8601_utc(UtcInstant{{2460748.75, 0.0}}), "2025-03-14T06:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(UtcInstant{{2451545.0, 9203.75}}), "2025-03-14T06:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(UtcInstant{{2460749.5, -0.75}}), "2025-03-14T06:00:00.000Z");
}

TEST(FormatIso8601, RoundsToMillisecondsWithCarry) {
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 14, 6, 0, 59.9994)), "2025-03-14T06:00:59.999Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 14, 6, 0, 59.9996)), "2025-03-14T06:01:00.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 14, 6, 59, 59.9996)), "2025-03-14T07:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 14, 23, 59, 59.9996)), "2025-03-15T00:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 31, 23, 59, 59.9996)), "2025-04-01T00:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2024, 12, 31, 23, 59, 59.9996)),
            "2025-01-01T00:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2024, 2, 28, 23, 59, 59.9999)), "2024-02-29T00:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2023, 2, 28, 23, 59, 59.9999)), "2023-03-01T00:00:00.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 14, 6, 0, 1.0004)), "2025-03-14T06:00:01.000Z");
  EXPECT_EQ(format_iso8601_utc(calendar(2025, 3, 14, 6, 0, 1.0006)), "2025-03-14T06:00:01.001Z");
}

TEST(FormatIso8601, MarksNonFiniteInstants) {
  const auto text = format_iso8601_utc(UtcInstant{{std::nan(""), 0.0}});
  EXPECT_EQ(text, "(invalid UTC instant)");
  EXPECT_FALSE(parse_iso8601_utc(text).ok());
}

// ---- seeded round trips ---------------------------------------------------------------------

// Property: any millisecond-resolution text in canonical form parses and formats back to itself.
TEST(Iso8601RoundTrip, CanonicalTextSurvivesParseAndFormat) {
  std::mt19937_64 rng(0x150860);
  std::uniform_int_distribution<int> year(1900, 2200), month(1, 12), day(1, 28), hour(0, 23),
      minute(0, 59), second(0, 59), ms(0, 999);
  for (int i = 0; i < 20000; ++i) {
    char text[32];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", year(rng), month(rng),
                  day(rng), hour(rng), minute(rng), second(rng), ms(rng));
    const auto t = parse_iso8601_utc(text);
    ASSERT_TRUE(t.ok()) << t.error().message;
    EXPECT_EQ(format_iso8601_utc(*t), text);
  }
}

// Property: formatting any instant and parsing the text back moves it by at most half a
// millisecond, and formatting is idempotent.
TEST(Iso8601RoundTrip, AnyInstantSurvivesFormatAndParseToHalfAMillisecond) {
  std::mt19937_64 rng(0x150861);
  std::uniform_real_distribution<double> unix_s(-2208988800.0, 7258118399.0);  // 1900 .. 2199
  for (int i = 0; i < 20000; ++i) {
    const auto t = UtcInstant::from_unix_seconds(unix_s(rng));
    const std::string text = format_iso8601_utc(t);
    const auto back = parse_iso8601_utc(text);
    ASSERT_TRUE(back.ok()) << text << ": " << back.error().message;
    EXPECT_LE(std::abs(seconds_between(t, *back)), 0.0005 + 1e-6) << text;
    EXPECT_EQ(format_iso8601_utc(*back), text);
  }
}

}  // namespace
