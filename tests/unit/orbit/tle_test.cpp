// TLE parsing: parse_tle, parse_tle_catalogue, tle_checksum, catalog_number, tle_epoch_to_jd.
//
// Sources of the worked values:
//  - ISS (ZARYA) 2008, the example set of Wikipedia's "Two-line element set" article; its two
//    checksums (7 and 7) are the ones printed there.
//  - Vanguard 1 (00005) and 88888 (blank international designator): SGP4-VER.TLE as shipped by
//    Debian python3-sgp4 2.15.
//  - ISS "December 32" (2019 day 366.82137887, i.e. 2020-01-01 19:42:47.134368): python-sgp4's
//    tests.py, test_december_32.
//  - Expected Julian dates: python3-sgp4 2.15 (the oracle), run as
//      /usr/bin/python3 -c "from sgp4.api import Satrec; s = Satrec.twoline2rv(l1, l2);
//                           print(s.jdsatepoch, s.jdsatepochF)"
//    ISS 2008 → 2454729.5 0.51782528; Vanguard → 2451722.5 0.78495062;
//    88888 → 2444513.5 0.98708465; December 32 → 2458849.5 0.82137887.
//    Python rounds its fraction to the TLE's 8 decimals while Vallado's jday (which we follow)
//    rebuilds it from hours, minutes and seconds, so fractions agree to ~1e-12 d, not bitwise.
//  - Alpha-5 numbers: Space-Track's alpha-5 table as quoted in python-sgp4's tests.py.

#include "azt/orbit/tle.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

namespace {

using azt::orbit::catalog_number;
using azt::orbit::parse_tle;
using azt::orbit::parse_tle_catalogue;
using azt::orbit::tle_checksum;

constexpr std::string_view kIssName = "ISS (ZARYA)";
constexpr std::string_view kIss1 =
    "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
constexpr std::string_view kIss2 =
    "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";
constexpr std::string_view kVanguard1 =
    "1 00005U 58002B   00179.78495062  .00000023  00000-0  28098-4 0  4753";
constexpr std::string_view kVanguard2 =
    "2 00005  34.2682 348.7242 1859667 331.7664  19.3264 10.82419157413667";
constexpr std::string_view kBlankDesignator1 =
    "1 88888U          80275.98708465  .00073094  13844-3  66816-4 0    87";
constexpr std::string_view kBlankDesignator2 =
    "2 88888  72.8435 115.9689 0086731  52.6988 110.5714 16.05824518  1058";

// Fraction-of-day tolerance between Vallado's jday and python's rounded fraction (see above):
// 1e-11 d is under a microsecond.
constexpr double kFractionTolerance = 1e-11;

bool contains(const std::string& haystack, std::string_view needle) {
  return haystack.find(needle) != std::string::npos;
}

/// `line` with columns first.. replaced by `text` and the checksum recomputed, to make one field
/// bad without also tripping the checksum. tle_checksum itself is checked on published lines.
std::string edit(std::string_view line, std::size_t first_column, std::string_view text) {
  std::string edited(line);
  edited.replace(first_column - 1, text.size(), text);
  edited[68] = static_cast<char>('0' + tle_checksum(edited));
  return edited;
}

std::string join(std::initializer_list<std::string_view> lines, std::string_view eol = "\n") {
  std::string text;
  for (std::string_view line : lines) {
    text += line;
    text += eol;
  }
  return text;
}

TEST(Tle, ChecksumOfPublishedLines) {
  EXPECT_EQ(tle_checksum(kIss1), 7);
  EXPECT_EQ(tle_checksum(kIss2), 7);
  EXPECT_EQ(tle_checksum(kVanguard1), 3);
  EXPECT_EQ(tle_checksum(kVanguard2), 7);
}

TEST(Tle, ParsesIssFields) {
  const auto r = parse_tle(kIss1, kIss2, kIssName);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->name, "ISS (ZARYA)");
  EXPECT_EQ(r->catalog, "25544");
  EXPECT_EQ(r->intl_designator, "98067A");
  EXPECT_EQ(r->classification, 'U');
  EXPECT_DOUBLE_EQ(r->mean_motion_dot, -0.00002182);
  EXPECT_DOUBLE_EQ(r->mean_motion_ddot, 0.0);
  EXPECT_DOUBLE_EQ(r->bstar, -0.11606e-4);
  EXPECT_DOUBLE_EQ(r->inclination_deg, 51.6416);
  EXPECT_DOUBLE_EQ(r->raan_deg, 247.4627);
  EXPECT_DOUBLE_EQ(r->eccentricity, 0.0006703);
  EXPECT_DOUBLE_EQ(r->arg_perigee_deg, 130.5360);
  EXPECT_DOUBLE_EQ(r->mean_anomaly_deg, 325.0288);
  EXPECT_DOUBLE_EQ(r->mean_motion_rev_day, 15.72125391);
  EXPECT_EQ(r->element_set_no, 292);
  EXPECT_EQ(r->rev_at_epoch, 56353);
  EXPECT_EQ(r->label(), "ISS (ZARYA)");
}

TEST(Tle, EpochMatchesPythonSgp4) {
  struct Case {
    std::string_view line1, line2;
    double whole, fraction;
  };
  const Case cases[] = {
      {kIss1, kIss2, 2454729.5, 0.51782528},
      {kVanguard1, kVanguard2, 2451722.5, 0.78495062},
      {kBlankDesignator1, kBlankDesignator2, 2444513.5, 0.98708465},
      {"1 25544U 98067A   19366.82137887  .00016717  00000-0  10270-3 0  9129",
       "2 25544  51.6392  96.6358 0005156  88.7140 271.4601 15.49497216  6061", 2458849.5,
       0.82137887},
  };
  for (const Case& c : cases) {
    const auto r = parse_tle(c.line1, c.line2);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->epoch_jd, c.whole) << c.line1;
    EXPECT_NEAR(r->epoch_jd_frac, c.fraction, kFractionTolerance) << c.line1;
  }
}

TEST(Tle, ExponentFieldsAndBlankDesignator) {
  const auto r = parse_tle(kBlankDesignator1, kBlankDesignator2);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->intl_designator, "");
  EXPECT_DOUBLE_EQ(r->mean_motion_ddot, 0.13844e-3);
  EXPECT_DOUBLE_EQ(r->bstar, 0.66816e-4);
  EXPECT_EQ(r->label(), "88888");
}

TEST(Tle, ChecksumErrorNamesLineAndColumn) {
  std::string bad(kIss2);
  bad[68] = '3';
  const auto r = parse_tle(kIss1, bad, kIssName);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(contains(r.error().message, "ISS (ZARYA): line 2, column 69: checksum"))
      << r.error().message;
  azt::orbit::TleOptions lax;
  lax.verify_checksum = false;
  EXPECT_TRUE(parse_tle(kIss1, bad, kIssName, lax).ok());
}

TEST(Tle, BadFieldsNamedWithColumn) {
  struct Case {
    int line;
    std::size_t column;
    std::string_view text;
    std::string_view expected;
  };
  const Case cases[] = {
      {1, 19, "0X264.51", "line 1, column 19: epoch: not a number"},
      {1, 21, "9X4.5178", "line 1, column 21: epoch: not a number"},
      {1, 21, "000.1000", "line 1, column 21: epoch: day of year out of range"},
      {1, 34, "-.0000x182", "line 1, column 34: first derivative of mean motion: not a number"},
      {1, 46, "0000x", "line 1, column 50: second derivative of mean motion: mantissa"},
      {1, 60, "*", "line 1, column 60: B*: exponent: a sign expected"},
      {1, 33, "x", "line 1, column 33: separator: a blank expected"},
      {1, 8, "X", "line 1, column 8: classification"},
      {2, 9, "181.0000", "line 2, column 9: inclination: out of range"},
      {2, 27, "00067a3", "line 2, column 32: eccentricity: not a digit"},
      {2, 53, "00.00000000", "line 2, column 53: mean motion: must be above 0"},
      {2, 3, "25545", "line 2, column 3: catalogue number: '25545' differs from line 1's"},
      {2, 3, "I5544", "line 2, column 3: catalogue number:"},
  };
  for (const Case& c : cases) {
    const std::string line1 = c.line == 1 ? edit(kIss1, c.column, c.text) : std::string(kIss1);
    const std::string line2 = c.line == 2 ? edit(kIss2, c.column, c.text) : std::string(kIss2);
    const auto r = parse_tle(line1, line2);
    ASSERT_FALSE(r.ok()) << c.expected;
    EXPECT_TRUE(contains(r.error().message, "25544: ")) << r.error().message;
    EXPECT_TRUE(contains(r.error().message, c.expected)) << r.error().message;
  }
}

TEST(Tle, LengthAndLineNumberChecked) {
  const auto short_line = parse_tle(kIss1.substr(0, 60), kIss2);
  ASSERT_FALSE(short_line.ok());
  EXPECT_TRUE(contains(short_line.error().message, "line 1, column 61: line: ends early"))
      << short_line.error().message;
  const auto long_line = parse_tle(kIss1, std::string(kIss2) + " 0.0 1440.0 360.0");
  ASSERT_FALSE(long_line.ok());
  EXPECT_TRUE(contains(long_line.error().message, "line 2, column 70:"))
      << long_line.error().message;
  const auto swapped = parse_tle(kIss2, kIss1);
  ASSERT_FALSE(swapped.ok());
  EXPECT_TRUE(contains(swapped.error().message, "line 1, column 1: line number: '1' expected"))
      << swapped.error().message;
  EXPECT_TRUE(parse_tle(std::string(kIss1) + "\r", std::string(kIss2) + "  ").ok());
}

TEST(Tle, Alpha5CatalogueNumbers) {
  struct Case {
    std::string_view text;
    long number;
  };
  const Case cases[] = {{"A0000", 100000}, {"A0001", 100001}, {"E8493", 148493},
                        {"J2931", 182931}, {"P4018", 234018}, {"W1928", 301928},
                        {"Z9999", 339999}, {"25544", 25544},  {"00005", 5}};
  for (const Case& c : cases) {
    const auto r = catalog_number(c.text);
    ASSERT_TRUE(r.ok()) << c.text << ": " << r.error().message;
    EXPECT_EQ(*r, c.number) << c.text;
  }
  for (std::string_view bad : {"I0001", "O0001", "a0001", "A001", "2554x", ""}) {
    EXPECT_FALSE(catalog_number(bad).ok()) << bad;
  }
  const auto set = parse_tle(edit(kIss1, 3, "A0001"), edit(kIss2, 3, "A0001"));
  ASSERT_TRUE(set.ok()) << set.error().message;
  EXPECT_EQ(set->catalog, "A0001");
  EXPECT_EQ(*catalog_number(set->catalog), 100001);
}

TEST(Tle, LeadingBlanksInCatalogueNumber) {
  // python-sgp4 #81: "1  4859U …" is number 4859.
  const auto r = parse_tle(edit(kIss1, 3, " 4859"), edit(kIss2, 3, " 4859"));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->catalog, "4859");
}

TEST(TleCatalogue, MixOfTwoAndThreeLineEntriesCrlfAndBlankLines) {
  const std::string text = join({kIssName, kIss1, kIss2, "", kVanguard1, kVanguard2, "   ",
                                 "0 TEST SAT", kBlankDesignator1, kBlankDesignator2},
                                "\r\n");
  const auto parsed = parse_tle_catalogue(text);
  EXPECT_TRUE(parsed.errors.empty()) << parsed.errors.front();
  ASSERT_EQ(parsed.sets.size(), 3U);
  EXPECT_EQ(parsed.sets[0].name, "ISS (ZARYA)");
  EXPECT_EQ(parsed.sets[1].name, "");
  EXPECT_EQ(parsed.sets[1].catalog, "00005");
  EXPECT_EQ(parsed.sets[2].name, "TEST SAT");
  EXPECT_EQ(parsed.sets[2].catalog, "88888");
}

TEST(TleCatalogue, BadEntryDoesNotHideTheGoodOnes) {
  // File lines: 1 name, 2–3 ISS; 4 name, 5–6 bad epoch; 7–8 Vanguard; 9 a lone first line;
  // 10 name, 11–12 88888.
  const std::string bad1 = edit(kIss1, 19, "XX");
  const std::string text = join({kIssName, kIss1, kIss2, "BROKEN", bad1, kIss2, kVanguard1,
                                 kVanguard2, kIss1, "LAST", kBlankDesignator1, kBlankDesignator2});
  const auto parsed = parse_tle_catalogue(text);
  ASSERT_EQ(parsed.sets.size(), 3U);
  EXPECT_EQ(parsed.sets[0].name, "ISS (ZARYA)");
  EXPECT_EQ(parsed.sets[1].catalog, "00005");
  EXPECT_EQ(parsed.sets[2].name, "LAST");
  ASSERT_EQ(parsed.errors.size(), 2U);
  EXPECT_EQ(parsed.errors[0], "BROKEN: line 5, column 19: epoch: not a number");
  EXPECT_TRUE(contains(parsed.errors[1], "25544: line 9: a first line without its second line"))
      << parsed.errors[1];
}

TEST(TleCatalogue, StrayLinesReported) {
  const std::string text = join({"NAME ONLY", "OTHER", kIss1, kIss2, kVanguard2});
  const auto parsed = parse_tle_catalogue(text);
  ASSERT_EQ(parsed.sets.size(), 1U);
  EXPECT_EQ(parsed.sets[0].name, "OTHER");
  ASSERT_EQ(parsed.errors.size(), 2U);
  EXPECT_EQ(parsed.errors[0], "NAME ONLY: line 1: a name without element lines");
  EXPECT_TRUE(contains(parsed.errors[1], "line 5: a second line without a first line"))
      << parsed.errors[1];
}

TEST(TleCatalogue, EmptyTextGivesNothing) {
  const auto parsed = parse_tle_catalogue("");
  EXPECT_TRUE(parsed.sets.empty());
  EXPECT_TRUE(parsed.errors.empty());
}

}  // namespace
