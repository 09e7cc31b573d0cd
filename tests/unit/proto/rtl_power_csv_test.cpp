// rtl_power's CSV lines (docs/calibration.md). The lines have the shape rtl-sdr's rtl_power.c
// prints in main() and csv_dbm(): strftime "%Y-%m-%d, %H:%M:%S", then "%i, %i, %.2f, %i, " (Hz low,
// Hz high, Hz step, samples), then "%.2f, " per bin and "%.2f\n" for the last (which repeats the
// bin before it). The numbers are a 1296 MHz hop of 1953.12 Hz bins (2.048 MS/s over 1024 bins).
#include "azt/proto/rtl_power_csv.hpp"

#include <gtest/gtest.h>

#include <array>
#include <charconv>
#include <cmath>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "test_support.hpp"

namespace azt::proto {
namespace {

constexpr std::string_view kHeader = "2024-01-02, 12:34:56, 1296000000, 1296500000, 1953.12, 10, ";

RtlPowerSweep parse_ok(std::string_view line) {
  auto parsed = parse_rtl_power_line(line);
  if (!parsed) {
    ADD_FAILURE() << "'" << line.substr(0, 120) << "': " << parsed.error().message;
    return {};
  }
  return *parsed;
}

std::string error_of(std::string_view line) {
  const auto parsed = parse_rtl_power_line(line);
  EXPECT_FALSE(parsed.ok()) << "accepted: '" << line.substr(0, 120) << "'";
  return parsed ? std::string() : parsed.error().message;
}

/// rtl_power's "%.2f".
std::string two_decimals(double value) {
  std::array<char, 64> buffer{};
  const auto [ptr, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                       std::chars_format::fixed, 2);
  EXPECT_EQ(ec, std::errc{});
  return {buffer.data(), ptr};
}

/// A line of `bins` bins of `db` each.
std::string line_of(std::size_t bins, std::string_view db = "-42.00") {
  std::string line(kHeader);
  for (std::size_t i = 0; i < bins; ++i) {
    if (i > 0) line += ", ";
    line += db;
  }
  return line + "\n";
}

TEST(RtlPowerCsv, ParsesAnRtlPowerLine) {
  const auto sweep = parse_ok(
      "2024-01-02, 12:34:56, 1296000000, 1296500000, 1953.12, 10, -42.10, -41.90, "
      "-41.95, -41.95\n");
  EXPECT_EQ(sweep.hz_low, 1296000000.0);
  EXPECT_EQ(sweep.hz_high, 1296500000.0);
  EXPECT_EQ(sweep.hz_step, 1953.12);
  EXPECT_EQ(sweep.samples, 10);
  EXPECT_EQ(sweep.bins_db, (std::vector<double>{-42.10, -41.90, -41.95, -41.95}));
}

TEST(RtlPowerCsv, ToleratesCrLfTabsAndNoSpaceAfterCommas) {
  EXPECT_EQ(parse_ok("2024-01-02,12:34:56,100,200,1.5,3,-1.00,2.00\r\n").bins_db,
            (std::vector<double>{-1.0, 2.0}));
  EXPECT_EQ(parse_ok("2024-01-02,\t12:34:56,  100, 200, 1.5, 3, -1.00,\t 2.00\r").bins_db,
            (std::vector<double>{-1.0, 2.0}));
  // Without a terminator (a datagram, or a line a reader already cut), and one bin.
  EXPECT_EQ(parse_ok("2024-01-02, 12:34:56, 100, 100, 1, 0, 5").bins_db,
            (std::vector<double>{5.0}));
  // Fractional seconds and Hz, as other sweepers that copy the format print them.
  EXPECT_EQ(parse_ok("2024-01-02, 12:34:56.25, 100.5, 200.5, 1.5, 3, 1").hz_low, 100.5);
}

TEST(RtlPowerCsv, TotalPowerIsTheMeanInLinearUnits) {
  // −10 dB and −20 dB are 0.1 and 0.01: their mean 0.055 is −12.5963731 dB (10·log10 0.055),
  // not the −15 dB a mean of the dB values would give.
  const auto two = parse_ok(std::string(kHeader) + "-10.00, -20.00\n");
  EXPECT_NEAR(sweep_power_db(two), -12.5963731, 1e-7);
  // 0, 0, 0 and 10 dB are 1, 1, 1 and 10: mean 3.25, 5.1188336 dB.
  const auto four = parse_ok(std::string(kHeader) + "0.00, 0.00, 0.00, 10.00\n");
  EXPECT_NEAR(sweep_power_db(four), 5.1188336, 1e-7);
  // A flat band is its own level.
  EXPECT_NEAR(sweep_power_db(parse_ok(line_of(1024))), -42.0, 1e-12);
  // The extremes the parser lets through neither overflow nor underflow.
  EXPECT_NEAR(sweep_power_db(parse_ok(std::string(kHeader) + "300, 300")), 300.0, 1e-9);
  EXPECT_NEAR(sweep_power_db(parse_ok(std::string(kHeader) + "-300, -300")), -300.0, 1e-9);
  EXPECT_TRUE(std::isnan(sweep_power_db(RtlPowerSweep{})));
}

TEST(RtlPowerCsv, RandomSweepsReadBackAndAverageBetweenTheirBins) {
  std::mt19937 rng(1600);  // seeded: the same sweeps every run
  std::uniform_real_distribution<double> db(-80.0, 20.0);
  std::uniform_int_distribution<std::size_t> count(1, 300);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> bins(count(rng));
    std::string line(kHeader);
    for (std::size_t i = 0; i < bins.size(); ++i) {
      bins[i] = db(rng);
      line += (i > 0 ? ", " : "") + two_decimals(bins[i]);
    }
    const auto sweep = parse_ok(line + "\n");
    ASSERT_EQ(sweep.bins_db.size(), bins.size());
    double lowest = 1e9;
    double highest = -1e9;
    double sum_db = 0.0;
    for (std::size_t i = 0; i < bins.size(); ++i) {
      EXPECT_NEAR(sweep.bins_db[i], bins[i], 0.005 + 1e-9);
      lowest = std::min(lowest, sweep.bins_db[i]);
      highest = std::max(highest, sweep.bins_db[i]);
      sum_db += sweep.bins_db[i];
    }
    const double total = sweep_power_db(sweep);
    EXPECT_GE(total, lowest - 1e-9);
    EXPECT_LE(total, highest + 1e-9);
    // The linear mean is never below the mean of the dB values (the log of a mean is at least
    // the mean of the logs), and it is dominated by the strongest bin.
    EXPECT_GE(total, sum_db / static_cast<double>(bins.size()) - 1e-9);
    EXPECT_GE(total, highest - 10.0 * std::log10(static_cast<double>(bins.size())) - 1e-9);
  }
}

TEST(RtlPowerCsv, RefusesMissingAndMalformedHeaderFields) {
  EXPECT_TRUE(test::contains(error_of(""), "empty"));
  EXPECT_TRUE(test::contains(error_of("\r\n"), "empty"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, 1.5"), "5 fields"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, 1.5, 3"), "no bins"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, 1.5, 3, "), "bin 1"));
  EXPECT_TRUE(test::contains(error_of("2024/01/02, 12:34:56, 100, 200, 1.5, 3, 1"), "date"));
  EXPECT_TRUE(test::contains(error_of(" 2024-01-02, 12:34:56, 100, 200, 1.5, 3, 1"), "date"));
  EXPECT_TRUE(test::contains(error_of(", 12:34:56, 100, 200, 1.5, 3, 1"), "date"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, , 100, 200, 1.5, 3, 1"), "time"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12h34, 100, 200, 1.5, 3, 1"), "time"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, abc, 200, 1.5, 3, 1"), "Hz low"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, -5, 200, 1.5, 3, 1"), "Hz low"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 300, 200, 1.5, 3, 1"), "Hz high"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, nan, 1.5, 3, 1"), "Hz high"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, 0, 3, 1"), "Hz step"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, -1, 3, 1"), "Hz step"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, 1, 1.5, 1"), "sample"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, 1, -1, 1"), "sample"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100, 200, 1, 9223372036854775808, 1"),
                             "sample"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 1e400, 1e401, 1, 3, 1"), "Hz low"));
  EXPECT_TRUE(test::contains(error_of("2024-01-02, 12:34:56, 100 , 200, 1, 3, 1"), "Hz low"));
}

TEST(RtlPowerCsv, RefusesEmptyAndNonFiniteBins) {
  // rtl_power prints these for a bin with no power or no samples: the sweep is unmeasured.
  for (const char* bad : {"nan", "-nan", "inf", "-inf", "NaN", "infinity"}) {
    const auto why = error_of(std::string(kHeader) + "-42.00, " + bad + ", -41.00\n");
    EXPECT_TRUE(test::contains(why, "bin 2 is not a finite number")) << why;
  }
  EXPECT_TRUE(
      test::contains(error_of(std::string(kHeader) + "-42.00, , -41.00"), "bin 2 is empty"));
  EXPECT_TRUE(test::contains(error_of(std::string(kHeader) + "-42.00,"), "bin 2 is empty"));
  EXPECT_TRUE(test::contains(error_of(std::string(kHeader) + "-42.00, -41.00, "), "bin 3"));
}

TEST(RtlPowerCsv, RefusesHostileNumbersAndJunk) {
  const std::string h(kHeader);
  EXPECT_TRUE(test::contains(error_of(h + "1e400"), "not a finite number"));
  EXPECT_TRUE(test::contains(error_of(h + "-1e400"), "not a finite number"));
  EXPECT_TRUE(test::contains(error_of(h + "1e300"), "out of range"));
  EXPECT_TRUE(test::contains(error_of(h + "-300.01"), "out of range"));
  EXPECT_TRUE(test::contains(error_of(h + std::string(400, '9')), "not a finite number"));
  EXPECT_TRUE(test::contains(error_of(h + "-42.1x"), "bin 1"));
  EXPECT_TRUE(test::contains(error_of(h + "-42.1 "), "bin 1"));     // junk after the number
  EXPECT_TRUE(test::contains(error_of(h + "-42.1\r\r"), "bin 1"));  // one "\r" only
  EXPECT_TRUE(test::contains(error_of(h + "-42.1.5"), "bin 1"));
  EXPECT_TRUE(test::contains(error_of(h + "0x10"), "bin 1"));
  EXPECT_TRUE(test::contains(error_of(h + "--4"), "bin 1"));
  EXPECT_TRUE(test::contains(error_of(h + "-42.00\n-41.00\n"), "bin 1"));  // two lines in one
  // An embedded NUL is junk, and is not copied into the message.
  const std::string nul = h + std::string("-42.0\0-1", 8);
  const std::string why = error_of(nul);
  EXPECT_TRUE(test::contains(why, "bin 1")) << why;
  EXPECT_EQ(why.find('\0'), std::string::npos);
  // A long field is quoted short.
  EXPECT_LT(error_of(h + std::string(100000, 'x')).size(), 120U);
}

TEST(RtlPowerCsv, BoundsTheNumberOfBins) {
  EXPECT_EQ(parse_ok(line_of(kRtlPowerMaxBins, "-1")).bins_db.size(), kRtlPowerMaxBins);
  EXPECT_TRUE(test::contains(error_of(line_of(kRtlPowerMaxBins + 1, "-1")), "more than 100000"));
  EXPECT_TRUE(test::contains(error_of(line_of(200000, "-1")), "more than 100000"));
}

}  // namespace
}  // namespace azt::proto
