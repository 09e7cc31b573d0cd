// The one-reading-a-line power feed (docs/calibration.md): what an SDR program, a script or
// `echo -42.1 | socat - udp:host:port` sends.
#include "azt/proto/power_line.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

#include "test_support.hpp"

namespace azt::proto {
namespace {

double parse_ok(std::string_view line) {
  const auto parsed = parse_power_line(line);
  if (!parsed) {
    ADD_FAILURE() << "'" << line << "': " << parsed.error().message;
    return 0.0;
  }
  return *parsed;
}

std::string error_of(std::string_view line) {
  const auto parsed = parse_power_line(line);
  EXPECT_FALSE(parsed.ok()) << "accepted: '" << line << "'";
  return parsed ? std::string() : parsed.error().message;
}

TEST(PowerLine, ParsesReadingsWithAndWithoutUnit) {
  EXPECT_EQ(parse_ok("-42.1"), -42.1);
  EXPECT_EQ(parse_ok("-41.87 dB"), -41.87);
  EXPECT_EQ(parse_ok("+3.5dB\r\n"), 3.5);
  EXPECT_EQ(parse_ok("  -7 db  "), -7.0);
  EXPECT_EQ(parse_ok("\t-0.5\t\r"), -0.5);
  EXPECT_EQ(parse_ok("4.2e1 DB"), 42.0);
  EXPECT_EQ(parse_ok("-12.25\tdB\n"), -12.25);
  EXPECT_EQ(parse_ok("0"), 0.0);
  EXPECT_EQ(parse_ok("300"), 300.0);
  EXPECT_EQ(parse_ok("-300 dB"), -300.0);
}

TEST(PowerLine, RefusesWhatIsNotOneReadingInDb) {
  EXPECT_TRUE(test::contains(error_of(""), "empty"));
  EXPECT_TRUE(test::contains(error_of(" \t\r\n"), "empty"));
  EXPECT_TRUE(test::contains(error_of("dB"), "no number"));
  EXPECT_TRUE(test::contains(error_of("  DB "), "no number"));
  for (const char* bad :
       {"nan",       "-nan",      "inf",         "-inf dB", "infinity", "1e400",    "-1e400",
        "-42.1 dBm", "-42.1 d B", "-42.1 dB dB", "42,1",    "0x10",     "- 42",     "42 42",
        "++5",       "+-5",       "5 W",         "abc",     "-42.1;",   "\"-42.1\""}) {
    EXPECT_TRUE(test::contains(error_of(bad), "not a finite number")) << bad;
  }
  EXPECT_TRUE(test::contains(error_of("300.01"), "beyond ±300 dB"));
  EXPECT_TRUE(test::contains(error_of("-1e300 dB"), "beyond ±300 dB"));
  EXPECT_TRUE(test::contains(error_of("-42.1\r\r"), "not a finite number"));  // one "\r" only
  EXPECT_TRUE(test::contains(error_of("-42.1\n-41.0"), "not a finite number"));
  const std::string nul("-42\0.1", 6);
  const std::string why = error_of(nul);
  EXPECT_TRUE(test::contains(why, "not a finite number")) << why;
  EXPECT_EQ(why.find('\0'), std::string::npos);
}

TEST(PowerLine, BoundsTheLine) {
  const std::string padded = std::string(60, ' ') + "-4.0";  // 64 characters: still a reading
  EXPECT_EQ(parse_ok(padded), -4.0);
  EXPECT_TRUE(test::contains(error_of(" " + padded), "longer than 64"));
  EXPECT_TRUE(test::contains(error_of(std::string(1 << 20, '9')), "longer than 64"));
}

TEST(PowerLine, SplitsADatagramIntoReadings) {
  const auto readings = parse_power_lines("-42.1\n-41.9 dB\r\n\n \t\nbad\n-40");
  ASSERT_EQ(readings.size(), 4U);
  EXPECT_EQ(*readings[0], -42.1);
  EXPECT_EQ(*readings[1], -41.9);
  EXPECT_FALSE(readings[2].ok());
  EXPECT_EQ(*readings[3], -40.0);
  EXPECT_TRUE(parse_power_lines("").empty());
  EXPECT_TRUE(parse_power_lines("\r\n\n").empty());
  ASSERT_EQ(parse_power_lines("-3 dB").size(), 1U);
}

}  // namespace
}  // namespace azt::proto
