// parse_finite_double: whole-string, locale-free, finite-only (docs/architecture.md: codecs pure
// and strict).

#include "azt/util/parse_number.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace {

using azt::parse_finite_double;

TEST(ParseFiniteDouble, AcceptsPlainDecimalAndExponentForms) {
  EXPECT_EQ(parse_finite_double("0"), 0.0);
  EXPECT_EQ(parse_finite_double("46.189"), 46.189);
  EXPECT_EQ(parse_finite_double("-79.393"), -79.393);
  EXPECT_EQ(parse_finite_double("1e3"), 1000.0);
  EXPECT_EQ(parse_finite_double("2.5E-2"), 0.025);
  EXPECT_EQ(parse_finite_double(".5"), 0.5);
  EXPECT_EQ(parse_finite_double("5."), 5.0);
  EXPECT_EQ(parse_finite_double("1.7976931348623157e308"), std::numeric_limits<double>::max());
}

TEST(ParseFiniteDouble, AcceptsOneLeadingPlus) {
  EXPECT_EQ(parse_finite_double("+12.5"), 12.5);
  EXPECT_EQ(parse_finite_double("+0"), 0.0);
}

TEST(ParseFiniteDouble, KeepsTheSignOfNegativeZero) {
  const auto v = parse_finite_double("-0");
  ASSERT_TRUE(v.has_value());
  EXPECT_TRUE(std::signbit(*v));
}

TEST(ParseFiniteDouble, RejectsEmptyAndSignsAlone) {
  EXPECT_FALSE(parse_finite_double(""));
  EXPECT_FALSE(parse_finite_double("+"));
  EXPECT_FALSE(parse_finite_double("-"));
  EXPECT_FALSE(parse_finite_double("."));
  EXPECT_FALSE(parse_finite_double("e5"));
}

// Regression: "+-5" used to parse as −5 (the '+' was stripped and from_chars took the '-').
TEST(ParseFiniteDouble, RejectsDoubledOrMixedSigns) {
  EXPECT_FALSE(parse_finite_double("++5"));
  EXPECT_FALSE(parse_finite_double("+-5"));
  EXPECT_FALSE(parse_finite_double("-+5"));
  EXPECT_FALSE(parse_finite_double("--5"));
}

TEST(ParseFiniteDouble, RejectsSurroundingSpaceAndTrailingJunk) {
  EXPECT_FALSE(parse_finite_double(" 1"));
  EXPECT_FALSE(parse_finite_double("1 "));
  EXPECT_FALSE(parse_finite_double("1\n"));
  EXPECT_FALSE(parse_finite_double("\t1"));
  EXPECT_FALSE(parse_finite_double("1x"));
  EXPECT_FALSE(parse_finite_double("1e"));
  EXPECT_FALSE(parse_finite_double("1.2.3"));
  EXPECT_FALSE(parse_finite_double("12deg"));
  // from_chars' default format has no hex floats: "0x10" reads as 0 followed by junk.
  EXPECT_FALSE(parse_finite_double("0x10"));
  // std::string_view can carry an embedded NUL; a C-string parser would stop there and accept.
  std::string with_nul = "15";
  with_nul[1] = '\0';
  EXPECT_FALSE(parse_finite_double(with_nul));
}

TEST(ParseFiniteDouble, IsLocaleFreeDecimalPointOnly) {
  EXPECT_FALSE(parse_finite_double("1,5"));
  EXPECT_FALSE(parse_finite_double("1_000"));
}

TEST(ParseFiniteDouble, RejectsNanInfinityAndOverflow) {
  for (const char* s : {"nan", "NaN", "-nan", "+nan", "nan(1)", "inf", "-inf", "+inf", "INF",
                        "infinity", "-Infinity", "1e309", "-1e309", "1e99999"}) {
    EXPECT_FALSE(parse_finite_double(s)) << s;
  }
}

// Property: the shortest to_chars text of any finite double parses back to the same bits.
TEST(ParseFiniteDouble, RoundTripsShortestTextOfRandomDoubles) {
  std::mt19937_64 rng(0x5eed0001);
  std::uniform_int_distribution<int> exponent(-300, 300);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  for (int i = 0; i < 20000; ++i) {
    const double x = mantissa(rng) * std::pow(10.0, exponent(rng));
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);
    ASSERT_EQ(ec, std::errc{});
    const std::string text(buf, end);
    const auto parsed = parse_finite_double(text);
    ASSERT_TRUE(parsed.has_value()) << text;
    EXPECT_EQ(*parsed, x) << text;
    if (x >= 0.0) {
      EXPECT_EQ(parse_finite_double("+" + text), x) << text;
    }
    EXPECT_FALSE(parse_finite_double(text + " ")) << text;
  }
}

}  // namespace
