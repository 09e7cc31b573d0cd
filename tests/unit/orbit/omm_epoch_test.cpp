// The OMM EPOCH reader of the core's element-set records (azt/orbit/omm_record.hpp): both CCSDS
// forms, microseconds, leap seconds, and refusals that say what is wrong.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>

#include "azt/orbit/omm_record.hpp"
#include "azt/orbit/tle.hpp"

namespace azt::orbit {
namespace {

TEST(OmmEpoch, CalendarAndDayOfYearFormsAgree) {
  const Result<JulianDate> calendar = parse_omm_epoch("2024-03-01T12:34:56.123456");
  const Result<JulianDate> day_of_year = parse_omm_epoch("2024-061T12:34:56.123456Z");
  ASSERT_TRUE(calendar.ok() && day_of_year.ok());
  EXPECT_EQ(calendar->whole, 2460370.5);  // 2024-03-01 0 h UTC
  EXPECT_EQ(calendar->whole, day_of_year->whole);
  EXPECT_EQ(calendar->fraction, day_of_year->fraction);
  EXPECT_NEAR(calendar->fraction, (12 * 3600 + 34 * 60 + 56.123456) / 86400.0, 1e-16);
  // The same split as the TLE parser: the whole part is the preceding midnight.
  const JulianDate tle = tle_epoch_to_jd(24, 61.5);
  EXPECT_EQ(calendar->whole, tle.whole);
  const Result<JulianDate> leap_day = parse_omm_epoch("2024-060T00:00:00");
  ASSERT_TRUE(leap_day.ok());
  EXPECT_EQ(leap_day->whole, 2460369.5);  // 2024-02-29
}

TEST(OmmEpoch, KeepsMicroseconds) {
  const Result<JulianDate> a = parse_omm_epoch("2024-03-01T23:59:59.999999");
  const Result<JulianDate> b = parse_omm_epoch("2024-03-01T23:59:59.999998");
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_NEAR((a->fraction - b->fraction) * 86400.0, 1e-6, 1e-10);
  EXPECT_LT(a->fraction, 1.0);
  const Result<JulianDate> leap = parse_omm_epoch("2016-12-31T23:59:60.5");
  ASSERT_TRUE(leap.ok()) << leap.error().message;
  EXPECT_EQ(leap->whole, parse_omm_epoch("2017-01-01T00:00:00")->whole);
}

TEST(OmmEpoch, RefusesWhatIsNotADate) {
  const auto message = [](std::string_view text) {
    const Result<JulianDate> jd = parse_omm_epoch(text);
    return jd.ok() ? std::string("accepted") : jd.error().message;
  };
  const std::string shape = " is not YYYY-MM-DDThh:mm:ss[.ffffff] or YYYY-DDDThh:mm:ss[.ffffff]";
  const std::pair<std::string_view, std::string> cases[] = {
      {"2024-03-01 12:00:00", "'2024-03-01 12:00:00'" + shape},
      {"2024-03-01T12:00", "'2024-03-01T12:00'" + shape},
      {"2024-03-01T12:00:00.", "'2024-03-01T12:00:00.'" + shape},
      {"2024-03-01T12:00:00+01:00", "'2024-03-01T12:00:00+01:00'" + shape},
      {"24-03-01T12:00:00", "'24-03-01T12:00:00'" + shape},
      {"2024-13-01T00:00:00", "month 13 out of range 1–12"},
      {"2023-02-29T00:00:00", "day 29 out of range 1–28"},
      {"2023-366T00:00:00", "day of year 366 out of range 1–365"},
      {"2024-000T00:00:00", "day of year 0 out of range 1–366"},
      {"2024-03-01T24:00:00", "time of day 24:00:00 out of range"},
      {"2024-03-01T12:00:60", "time of day 12:00:60 out of range"},
      {"1956-12-31T00:00:00", "year 1956 out of range 1957–2099"},
  };
  for (const auto& [text, refusal] : cases) EXPECT_EQ(message(text), refusal) << text;
}

}  // namespace
}  // namespace azt::orbit
