// UtcInstant construction and make_time_scales (UTC -> TT, UT1).
//
// Sources of the worked values:
//  - ERFA's test suite (t_erfa_c.c): t_cal2jd, t_utctai, t_taitt, t_utcut1.
//  - The oracle README (/work/shared/oracles/README.md): 2025-03-14 06:00:00 UTC is UT JD
//    2460748.75; with ΔT_swe the same instant has TT JD 2460748.750800741 and, for
//    UT1 = UTC + 0.203387 s, UT1 JD 2460748.750002354 (swetest header lines).
//  - IERS Bulletin C 52: TAI - UTC = 36 s until 2016-12-31, 37 s from 2017-01-01.
//  - Unix time: 0 = 1970-01-01T00:00Z = MJD 40587 (POSIX epoch); 1741932000 = 2025-03-14T06:00Z
//    (Python datetime.timestamp()).

#include "azt/astro/time_scales.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace {

using azt::astro::LeapSecondTable;
using azt::astro::make_time_scales;
using azt::astro::UtcInstant;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

using azt::test::calendar;
using azt::test::contains;

// ---- UtcInstant::from_calendar --------------------------------------------------------------

TEST(UtcFromCalendar, MatchesErfaCal2jdExample) {
  // ERFA t_cal2jd: 2003-06-01 -> djm0 2400000.5, djm 52791.0.
  const auto t = calendar(2003, 6, 1, 0, 0, 0.0);
  EXPECT_EQ(t.jd.jd1, 2400000.5 + 52791.0);
  EXPECT_EQ(t.jd.jd2, 0.0);
  EXPECT_EQ(t.mjd(), 52791.0);
}

TEST(UtcFromCalendar, OracleInstantIsJd2460748_75) {
  const auto t = calendar(2025, 3, 14, 6, 0, 0.0);
  EXPECT_EQ(t.jd.jd1, 2460748.5);
  EXPECT_EQ(t.jd.jd2, 0.25);
  EXPECT_EQ(t.jd.total(), 2460748.75);
  EXPECT_EQ(t.mjd(), 60748.25);
}

TEST(UtcFromCalendar, KeepsMicrosecondsInTheSmallPart) {
  const auto a = calendar(2025, 3, 14, 6, 0, 0.0);
  const auto b = calendar(2025, 3, 14, 6, 0, 0.000001);
  EXPECT_EQ(a.jd.jd1, b.jd.jd1);
  EXPECT_NEAR((b.jd.jd2 - a.jd.jd2) * 86400.0, 1e-6, 1e-12);
}

TEST(UtcFromCalendar, AcceptsLeapDaysAndRangeEnds) {
  EXPECT_TRUE(UtcInstant::from_calendar(2024, 2, 29, 0, 0, 0.0).ok());
  EXPECT_TRUE(UtcInstant::from_calendar(2000, 2, 29, 0, 0, 0.0).ok());  // 400-year rule
  EXPECT_TRUE(UtcInstant::from_calendar(1900, 1, 1, 0, 0, 0.0).ok());
  EXPECT_TRUE(UtcInstant::from_calendar(2200, 12, 31, 23, 59, 59.999999).ok());
  EXPECT_TRUE(UtcInstant::from_calendar(2025, 1, 31, 0, 0, 0.0).ok());
  EXPECT_TRUE(UtcInstant::from_calendar(2025, 12, 31, 0, 0, 0.0).ok());
}

void expect_calendar_error(int y, int mo, int d, int h, int mi, double s,
                           const std::string& words) {
  const auto r = UtcInstant::from_calendar(y, mo, d, h, mi, s);
  ASSERT_FALSE(r.ok()) << words;
  EXPECT_TRUE(contains(r.error().message, words)) << r.error().message;
}

TEST(UtcFromCalendar, RejectsImpossibleDatesAndTimes) {
  expect_calendar_error(1899, 12, 31, 0, 0, 0.0, "year 1899");
  expect_calendar_error(2201, 1, 1, 0, 0, 0.0, "year 2201");
  expect_calendar_error(2025, 0, 1, 0, 0, 0.0, "month 0");
  expect_calendar_error(2025, 13, 1, 0, 0, 0.0, "month 13");
  expect_calendar_error(2025, 1, 0, 0, 0, 0.0, "day 0");
  expect_calendar_error(2025, 1, 32, 0, 0, 0.0, "day 32");
  expect_calendar_error(2025, 4, 31, 0, 0, 0.0, "day 31 is not in 1..30");
  expect_calendar_error(2023, 2, 29, 0, 0, 0.0, "day 29 is not in 1..28 in 2023-02");
  expect_calendar_error(1900, 2, 29, 0, 0, 0.0, "day 29");  // century, not a leap year
  expect_calendar_error(2025, 1, 1, -1, 0, 0.0, "hour -1");
  expect_calendar_error(2025, 1, 1, 24, 0, 0.0, "hour 24");
  expect_calendar_error(2025, 1, 1, 0, 60, 0.0, "minute 60");
  expect_calendar_error(2025, 1, 1, 0, -1, 0.0, "minute -1");
  expect_calendar_error(2025, 1, 1, 0, 0, 60.0, "second 60");
  expect_calendar_error(2025, 1, 1, 0, 0, -0.001, "second -0.001");
  expect_calendar_error(2025, 1, 1, 0, 0, kNan, "second nan");
  expect_calendar_error(2025, 1, 1, 0, 0, kInf, "second inf");
}

// ---- UtcInstant::from_unix_seconds ----------------------------------------------------------

TEST(UtcFromUnix, EpochIsMjd40587) {
  const auto t = UtcInstant::from_unix_seconds(0.0);
  EXPECT_EQ(t.mjd(), 40587.0);
  EXPECT_EQ(t.jd.jd1, 2440587.5);
  EXPECT_EQ(t.jd.jd2, 0.0);
}

TEST(UtcFromUnix, OracleInstant) {
  const auto t = UtcInstant::from_unix_seconds(1741932000.0);
  EXPECT_EQ(t.jd.jd1, 2460748.5);
  EXPECT_EQ(t.jd.jd2, 0.25);
}

TEST(UtcFromUnix, KeepsSubMillisecondPartOfModernTimestamps) {
  // 1741932000.000125 is stored with ~0.24 µs resolution; the day split must not lose more.
  const double unix_s = 1741932000.000125;
  const auto t = UtcInstant::from_unix_seconds(unix_s);
  EXPECT_EQ(t.jd.jd1, 2460748.5);
  EXPECT_NEAR(t.jd.jd2 * 86400.0, 21600.000125, 3e-7);
}

TEST(UtcFromUnix, UnixSecondsIsTheInverse) {
  EXPECT_EQ(UtcInstant::from_unix_seconds(0.0).unix_seconds(), 0.0);
  EXPECT_EQ(UtcInstant::from_unix_seconds(1741932000.0).unix_seconds(), 1741932000.0);
  EXPECT_NEAR(UtcInstant::from_unix_seconds(1741932000.000125).unix_seconds(), 1741932000.000125,
              3e-7);
  EXPECT_NEAR(UtcInstant::from_unix_seconds(-0.5).unix_seconds(), -0.5, 1e-9);
  const auto parsed = azt::astro::parse_iso8601_utc("2025-03-01T00:00:00Z");
  ASSERT_TRUE(parsed.ok());
  EXPECT_EQ(parsed->unix_seconds(), 1740787200.0);
}

TEST(UtcFromUnix, HandlesTimesBefore1970) {
  const auto t = UtcInstant::from_unix_seconds(-0.5);  // 1969-12-31T23:59:59.5Z
  EXPECT_EQ(t.jd.jd1, 2440586.5);
  EXPECT_NEAR(t.jd.jd2 * 86400.0, 86399.5, 1e-9);
  const auto day = UtcInstant::from_unix_seconds(-86400.0);  // 1969-12-31T00:00Z
  EXPECT_EQ(day.mjd(), 40586.0);
  // A hair before midnight must not land on the wrong day or outside [0, 1).
  const auto hair = UtcInstant::from_unix_seconds(-1e-13);
  EXPECT_GE(hair.jd.jd2, 0.0);
  EXPECT_LT(hair.jd.jd2, 1.0);
  EXPECT_NEAR(hair.mjd(), 40587.0, 1e-12);
}

TEST(UtcFromUnix, AgreesWithCalendarAtRandomWholeSeconds) {
  // Property: counting whole days from 1970 and whole seconds within the day gives the same
  // instant as the calendar constructor for that day (days from the calendar, not recomputed).
  std::mt19937_64 rng(0x7153ca1e);
  std::uniform_int_distribution<int> day_of_epoch(0, 60000);  // 1970 .. 2134
  std::uniform_int_distribution<int> second_of_day(0, 86399);
  const auto epoch = calendar(1970, 1, 1, 0, 0, 0.0);
  for (int i = 0; i < 5000; ++i) {
    const int days = day_of_epoch(rng);
    const int secs = second_of_day(rng);
    const auto t = UtcInstant::from_unix_seconds(days * 86400.0 + secs);
    EXPECT_EQ(t.jd.jd1, epoch.jd.jd1 + days);
    EXPECT_NEAR(t.jd.jd2 * 86400.0, secs, 1e-9);
  }
}

// ---- make_time_scales ------------------------------------------------------------------------

TEST(MakeTimeScales, MatchesErfaUtcTaiTtAndUt1Examples) {
  // ERFA t_utctai: UTC (2453750.5, 0.892100694) -> TAI (2453750.5, 0.8924826384444444444).
  // ERFA t_taitt: TAI 0.892482639 -> TT 0.892855139, i.e. TT - TAI = 0.0003725 d (32.184 s);
  // so TT = 0.8924826384444444444 + 0.0003725 = 0.8928551384444444444.
  // ERFA t_utcut1: UTC 0.892100694 with DUT1 0.3341 s -> UT1 0.8921045608981481481.
  const UtcInstant utc{{2453750.5, 0.892100694}};
  const auto ts = make_time_scales(utc, 0.3341, LeapSecondTable::builtin());
  ASSERT_TRUE(ts.ok()) << ts.error().message;
  EXPECT_EQ(ts->tai_minus_utc_s, 33.0);
  EXPECT_EQ(ts->dut1_s, 0.3341);
  EXPECT_EQ(ts->tt.jd1, 2453750.5);
  EXPECT_NEAR(ts->tt.jd2, 0.8928551384444444444, 1e-12);
  EXPECT_EQ(ts->ut1.jd1, 2453750.5);
  EXPECT_NEAR(ts->ut1.jd2, 0.8921045608981481481, 1e-12);
  EXPECT_EQ(ts->utc.jd.jd2, 0.892100694);
  EXPECT_FALSE(ts->leap_table_expired);
}

TEST(MakeTimeScales, MatchesOracleReadmeInstant) {
  const auto ts =
      make_time_scales(calendar(2025, 3, 14, 6, 0, 0.0), 0.203387, LeapSecondTable::builtin());
  ASSERT_TRUE(ts.ok()) << ts.error().message;
  EXPECT_EQ(ts->tai_minus_utc_s, 37.0);
  EXPECT_NEAR(ts->tt.total(), 2460748.750800741, 1e-9);   // "TT:  2460748.750800741"
  EXPECT_NEAR(ts->ut1.total(), 2460748.750002354, 1e-9);  // "UT:  2460748.750002354"
  EXPECT_FALSE(ts->leap_table_expired);
}

TEST(MakeTimeScales, StepsByTheLeapSecondAtTheEndOf2016) {
  // Bulletin C 52: one UTC second from 23:59:59 to 00:00:00 spans two seconds of TT.
  const auto before =
      make_time_scales(calendar(2016, 12, 31, 23, 59, 59.0), 0.0, LeapSecondTable::builtin());
  const auto after =
      make_time_scales(calendar(2017, 1, 1, 0, 0, 0.0), 0.0, LeapSecondTable::builtin());
  ASSERT_TRUE(before.ok() && after.ok());
  EXPECT_EQ(before->tai_minus_utc_s, 36.0);
  EXPECT_EQ(after->tai_minus_utc_s, 37.0);
  const double tt_gap_s =
      ((after->tt.jd1 - before->tt.jd1) + (after->tt.jd2 - before->tt.jd2)) * 86400.0;
  EXPECT_NEAR(tt_gap_s, 2.0, 1e-6);
}

TEST(MakeTimeScales, KeepsMicrosecondsInTtAndUt1) {
  const auto a =
      make_time_scales(calendar(2025, 3, 14, 6, 0, 0.0), 0.1, LeapSecondTable::builtin());
  const auto b =
      make_time_scales(calendar(2025, 3, 14, 6, 0, 0.000001), 0.1, LeapSecondTable::builtin());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_NEAR((b->tt.jd2 - a->tt.jd2) * 86400.0, 1e-6, 1e-11);
  EXPECT_NEAR((b->ut1.jd2 - a->ut1.jd2) * 86400.0, 1e-6, 1e-11);
}

TEST(MakeTimeScales, FlagsInstantsAfterTheTableExpiry) {
  // Builtin expiry: 2026-06-28 (MJD 61219), from tzdata 2025b's leap-seconds.list.
  const auto& table = LeapSecondTable::builtin();
  const auto at = make_time_scales(calendar(2026, 6, 28, 0, 0, 0.0), 0.0, table);
  const auto later = make_time_scales(calendar(2026, 6, 29, 0, 0, 0.0), 0.0, table);
  ASSERT_TRUE(at.ok() && later.ok());
  EXPECT_FALSE(at->leap_table_expired);
  EXPECT_TRUE(later->leap_table_expired);
  EXPECT_EQ(later->tai_minus_utc_s, 37.0);  // still the last known value
}

TEST(MakeTimeScales, AcceptsDut1UpToTheHardLimit) {
  const auto t = calendar(2025, 3, 14, 6, 0, 0.0);
  EXPECT_TRUE(make_time_scales(t, 0.95, LeapSecondTable::builtin()).ok());  // beyond nominal 0.9
  EXPECT_TRUE(make_time_scales(t, 10.0, LeapSecondTable::builtin()).ok());
  EXPECT_TRUE(make_time_scales(t, -10.0, LeapSecondTable::builtin()).ok());
}

TEST(MakeTimeScales, RejectsBadDut1WithTheLimits) {
  const auto t = calendar(2025, 3, 14, 6, 0, 0.0);
  for (const double dut1 : {10.001, -10.5, 1e300, kNan, kInf, -kInf}) {
    const auto ts = make_time_scales(t, dut1, LeapSecondTable::builtin());
    ASSERT_FALSE(ts.ok()) << dut1;
    EXPECT_TRUE(contains(ts.error().message, "DUT1")) << ts.error().message;
    EXPECT_TRUE(contains(ts.error().message, "[-10, 10]")) << ts.error().message;
  }
}

TEST(MakeTimeScales, RejectsInstantsBefore1972) {
  const auto ts =
      make_time_scales(calendar(1971, 12, 31, 23, 59, 59.0), 0.0, LeapSecondTable::builtin());
  ASSERT_FALSE(ts.ok());
  EXPECT_TRUE(contains(ts.error().message, "1972-01-01")) << ts.error().message;
  EXPECT_TRUE(make_time_scales(calendar(1972, 1, 1, 0, 0, 0.0), 0.0, LeapSecondTable::builtin()));
}

TEST(MakeTimeScales, RejectsNonFiniteInstants) {
  const UtcInstant bad{{kNan, 0.0}};
  EXPECT_FALSE(make_time_scales(bad, 0.0, LeapSecondTable::builtin()).ok());
}

TEST(MakeTimeScales, UsesTheGivenTable) {
  // A table that starts on 2017-01-01 (NTP 3692217600) knows nothing about 2016.
  const auto table = LeapSecondTable::parse_ietf_list("#@ 3991593600\n3692217600 37\n");
  ASSERT_TRUE(table.ok()) << table.error().message;
  const auto ts = make_time_scales(calendar(2016, 6, 1, 0, 0, 0.0), 0.0, *table);
  ASSERT_FALSE(ts.ok());
  EXPECT_TRUE(contains(ts.error().message, "57754")) << ts.error().message;
}

// Property: TT never runs slower than UTC; between two instants it gains exactly the leap
// seconds inserted in between (a whole number, 0..27 since 1972), and UT1 - UTC is DUT1.
TEST(MakeTimeScales, RandomPairsGainWholeLeapSeconds) {
  std::mt19937_64 rng(0x77ca1e5);
  std::uniform_real_distribution<double> unix_s(63072000.0, 1900000000.0);  // 1972 .. 2030
  std::uniform_real_distribution<double> dut1(-0.9, 0.9);
  const auto& table = LeapSecondTable::builtin();
  for (int i = 0; i < 5000; ++i) {
    double a = unix_s(rng);
    double b = unix_s(rng);
    if (a > b) std::swap(a, b);
    const double d = dut1(rng);
    const auto ta = make_time_scales(UtcInstant::from_unix_seconds(a), d, table);
    const auto tb = make_time_scales(UtcInstant::from_unix_seconds(b), d, table);
    ASSERT_TRUE(ta.ok() && tb.ok());
    const double tt_span_s = ((tb->tt.jd1 - ta->tt.jd1) + (tb->tt.jd2 - ta->tt.jd2)) * 86400.0;
    const double gained_s = tt_span_s - (b - a);
    EXPECT_GE(gained_s, -1e-5);
    EXPECT_LE(gained_s, 27.0 + 1e-5);
    EXPECT_NEAR(gained_s, std::round(gained_s), 1e-5) << a << " " << b;
    EXPECT_NEAR(((ta->ut1.jd1 - ta->utc.jd.jd1) + (ta->ut1.jd2 - ta->utc.jd.jd2)) * 86400.0, d,
                1e-9);
  }
}

}  // namespace
