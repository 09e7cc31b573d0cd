// Maidenhead locators: decode_locator / encode_locator.
//
// Sources of the worked values:
//  - Seed document /work/shared/seeds/000_70c4f74ac397fdfb.txt: "GridCode FN06HE, Lat 46.189000,
//    Lon -79.393000"; the header comment of maidenhead.hpp gives FN06HE's centre 46.1875 N,
//    79.375 W.
//  - Hamlib 4.5.4 (Debian libhamlib-utils), `rotctl -m 1` commands `L lon lat 10` (encode,
//    prints upper case) and `l LOCATOR` (decode, prints the centre to 6 decimals):
//      L -79.393 46.189 10    -> FN06HE25UI      l FN06he25ui -> -79.392882  46.188976
//      L 11.578 48.137 10     -> JN58SD92IV      l JN58td     ->  11.625000  48.145833
//      L 0 0 10               -> JJ00AA00AA      l JN58TD25   ->  11.604167  48.147917
//      L -0.0001 -0.0001 10   -> II99XX99XX      l AA00aa00aa -> -179.999826 -89.999913
//      L 179.9999 89.9999 10  -> RR99XX99XX      l FN06       ->  -79.000000  46.500000
//    (Hamlib wraps longitude 180 to AA; our header puts 180 and 90 in the last square instead.)

#include "azt/astro/maidenhead.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace {

using azt::astro::decode_locator;
using azt::astro::encode_locator;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

std::string encode(double lat, double lon, int chars) {
  const auto r = encode_locator(lat, lon, chars);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return r.ok() ? *r : std::string();
}

// ---- decode ---------------------------------------------------------------------------------

TEST(DecodeLocator, SeedSquareFN06HE) {
  const auto sq = decode_locator("FN06HE");
  ASSERT_TRUE(sq.ok()) << sq.error().message;
  EXPECT_DOUBLE_EQ(sq->lat_deg, 46.1875);
  EXPECT_DOUBLE_EQ(sq->lon_deg, -79.375);
  EXPECT_DOUBLE_EQ(sq->height_deg, 2.5 / 60.0);  // subsquare 2.5' x 5'
  EXPECT_DOUBLE_EQ(sq->width_deg, 5.0 / 60.0);
  // The seed's station lies inside it.
  EXPECT_LE(std::abs(46.189 - sq->lat_deg), sq->height_deg / 2);
  EXPECT_LE(std::abs(-79.393 - sq->lon_deg), sq->width_deg / 2);
}

TEST(DecodeLocator, IsCaseInsensitive) {
  for (const char* loc : {"fn06he", "FN06he", "fN06hE"}) {
    const auto sq = decode_locator(loc);
    ASSERT_TRUE(sq.ok()) << loc << ": " << sq.error().message;
    EXPECT_DOUBLE_EQ(sq->lat_deg, 46.1875) << loc;
    EXPECT_DOUBLE_EQ(sq->lon_deg, -79.375) << loc;
  }
}

TEST(DecodeLocator, MatchesHamlibCentresAndGivesEachLevelsSize) {
  struct Case {
    const char* loc;
    double lon, lat, width, height;
  };
  const Case cases[] = {
      {"FN06", -79.0, 46.5, 2.0, 1.0},
      {"JN58td", 11.625, 48.145833, 5.0 / 60, 2.5 / 60},
      {"JN58TD25", 11.604167, 48.147917, 0.5 / 60, 0.25 / 60},
      {"FN06he25ui", -79.392882, 46.188976, 1.25 / 3600, 0.625 / 3600},
      {"AA00aa00aa", -179.999826, -89.999913, 1.25 / 3600, 0.625 / 3600},
  };
  for (const auto& c : cases) {
    const auto sq = decode_locator(c.loc);
    ASSERT_TRUE(sq.ok()) << c.loc << ": " << sq.error().message;
    EXPECT_NEAR(sq->lon_deg, c.lon, 5e-7) << c.loc;  // Hamlib prints 6 decimals
    EXPECT_NEAR(sq->lat_deg, c.lat, 5e-7) << c.loc;
    EXPECT_DOUBLE_EQ(sq->width_deg, c.width) << c.loc;
    EXPECT_DOUBLE_EQ(sq->height_deg, c.height) << c.loc;
  }
}

TEST(DecodeLocator, CornersOfTheGrid) {
  const auto first = decode_locator("AA00");
  ASSERT_TRUE(first.ok());
  EXPECT_DOUBLE_EQ(first->lon_deg, -179.0);
  EXPECT_DOUBLE_EQ(first->lat_deg, -89.5);
  const auto last = decode_locator("RR99xx");
  ASSERT_TRUE(last.ok());
  EXPECT_DOUBLE_EQ(last->lon_deg, 180.0 - 2.5 / 60);
  EXPECT_DOUBLE_EQ(last->lat_deg, 90.0 - 1.25 / 60);
}

void expect_decode_error(std::string_view loc, const std::string& words) {
  const auto sq = decode_locator(loc);
  ASSERT_FALSE(sq.ok()) << "accepted: " << loc;
  EXPECT_TRUE(contains(sq.error().message, words)) << sq.error().message;
}

TEST(DecodeLocator, RejectsBadLengths) {
  expect_decode_error("", "has 0 characters");
  expect_decode_error("F", "has 1 characters");
  expect_decode_error("FN", "has 2 characters");
  expect_decode_error("FN0", "has 3 characters");
  expect_decode_error("FN06h", "has 5 characters");
  expect_decode_error("FN06he2", "has 7 characters");
  expect_decode_error("FN06he25u", "has 9 characters");
  expect_decode_error("FN06he25uiAA", "has 12 characters");
  expect_decode_error("FN06 ", "has 5 characters");
}

TEST(DecodeLocator, NamesTheBadCharacterAndItsPosition) {
  expect_decode_error("SN06", "character 'S' at position 1");
  expect_decode_error("FS06", "character 'S' at position 2");
  expect_decode_error("FNA6", "character 'A' at position 3");
  expect_decode_error("FN0x", "character 'x' at position 4");
  expect_decode_error("FN06ye", "character 'y' at position 5");
  expect_decode_error("FN06hY", "character 'Y' at position 6");
  expect_decode_error("FN06he2u", "character 'u' at position 8");
  expect_decode_error("FN06he25z1", "character 'z' at position 9");
  expect_decode_error("FN06he25u5", "character '5' at position 10");
  expect_decode_error("F-06", "character '-' at position 2");
}

TEST(DecodeLocator, SaysWhatWasExpected) {
  expect_decode_error("1N06", "A-R");
  expect_decode_error("FNx6", "0-9");
  expect_decode_error("FN06h!", "a-x");
}

// ---- encode ---------------------------------------------------------------------------------

TEST(EncodeLocator, SeedStationIsFN06he) {
  EXPECT_EQ(encode(46.189, -79.393, 4), "FN06");
  EXPECT_EQ(encode(46.189, -79.393, 6), "FN06he");
  EXPECT_EQ(encode(46.189, -79.393, 8), "FN06he25");
  EXPECT_EQ(encode(46.189, -79.393, 10), "FN06he25ui");
}

TEST(EncodeLocator, MatchesHamlib) {
  EXPECT_EQ(encode(48.137, 11.578, 10), "JN58sd92iv");
  EXPECT_EQ(encode(0.0, 0.0, 10), "JJ00aa00aa");
  EXPECT_EQ(encode(-0.0001, -0.0001, 10), "II99xx99xx");
  EXPECT_EQ(encode(89.9999, 179.9999, 10), "RR99xx99xx");
  EXPECT_EQ(encode(-90.0, -180.0, 10), "AA00aa00aa");
}

TEST(EncodeLocator, PutsTheFarEdgesInTheLastSquare) {
  EXPECT_EQ(encode(90.0, 180.0, 10), "RR99xx99xx");
  EXPECT_EQ(encode(90.0, 0.0, 6), "JR09ax");
  EXPECT_EQ(encode(0.0, 180.0, 4), "RJ90");
}

void expect_encode_error(double lat, double lon, int chars, const std::string& words) {
  const auto r = encode_locator(lat, lon, chars);
  ASSERT_FALSE(r.ok()) << "accepted: " << lat << " " << lon << " " << chars;
  EXPECT_TRUE(contains(r.error().message, words)) << r.error().message;
}

TEST(EncodeLocator, RejectsBadLengthsAndCoordinates) {
  for (const int chars : {-4, 0, 2, 3, 5, 7, 9, 11, 12}) {
    expect_encode_error(46.0, -79.0, chars, "length " + std::to_string(chars));
  }
  expect_encode_error(90.001, 0.0, 6, "latitude");
  expect_encode_error(-91.0, 0.0, 6, "latitude");
  expect_encode_error(kNan, 0.0, 6, "latitude");
  expect_encode_error(0.0, 180.001, 6, "longitude");
  expect_encode_error(0.0, -181.0, 6, "longitude");
  expect_encode_error(0.0, kNan, 6, "longitude");
  expect_encode_error(0.0, std::numeric_limits<double>::infinity(), 6, "longitude");
}

// ---- seeded properties ----------------------------------------------------------------------

// Property: for every length, the square a point encodes to contains the point; longer locators
// extend shorter ones; the locator re-encodes from its own centre to itself.
TEST(LocatorRoundTrip, EncodedSquareContainsThePoint) {
  std::mt19937_64 rng(0x3a1de4ead);
  std::uniform_real_distribution<double> lat(-90.0, 90.0), lon(-180.0, 180.0);
  const double slack_deg = 1e-9;
  for (int i = 0; i < 20000; ++i) {
    const double la = lat(rng), lo = lon(rng);
    std::string previous;
    for (const int chars : {4, 6, 8, 10}) {
      const std::string loc = encode(la, lo, chars);
      ASSERT_EQ(loc.size(), static_cast<std::size_t>(chars));
      EXPECT_EQ(loc.substr(0, previous.size()), previous) << loc;
      previous = loc;
      const auto sq = decode_locator(loc);
      ASSERT_TRUE(sq.ok()) << loc << ": " << sq.error().message;
      EXPECT_LE(std::abs(la - sq->lat_deg), sq->height_deg / 2 + slack_deg) << loc << " " << la;
      EXPECT_LE(std::abs(lo - sq->lon_deg), sq->width_deg / 2 + slack_deg) << loc << " " << lo;
      EXPECT_EQ(encode(sq->lat_deg, sq->lon_deg, chars), loc);
    }
  }
}

// Property: every syntactically valid random locator decodes, and its centre encodes back to it
// (in canonical case: fields upper, the rest lower).
TEST(LocatorRoundTrip, RandomLocatorsDecodeAndReencode) {
  std::mt19937_64 rng(0x3a1de4eae);
  std::uniform_int_distribution<int> field(0, 17), digit(0, 9), sub(0, 23);
  std::bernoulli_distribution upper(0.5);
  for (int i = 0; i < 20000; ++i) {
    std::string canonical;
    std::string mixed;
    const auto add = [&](char c, bool letter) {
      canonical += c;
      mixed += letter && upper(rng) ? static_cast<char>(c ^ 0x20) : c;
    };
    add(static_cast<char>('A' + field(rng)), true);
    add(static_cast<char>('A' + field(rng)), true);
    add(static_cast<char>('0' + digit(rng)), false);
    add(static_cast<char>('0' + digit(rng)), false);
    const int pairs = i % 4;  // 0..3 more pairs: 4, 6, 8 or 10 characters
    for (int p = 0; p < pairs; ++p) {
      const bool letters = p % 2 == 0;
      for (int k = 0; k < 2; ++k) {
        add(static_cast<char>(letters ? 'a' + sub(rng) : '0' + digit(rng)), letters);
      }
    }
    const auto sq = decode_locator(mixed);
    ASSERT_TRUE(sq.ok()) << mixed << ": " << sq.error().message;
    EXPECT_EQ(encode(sq->lat_deg, sq->lon_deg, static_cast<int>(canonical.size())), canonical)
        << mixed;
  }
}

}  // namespace
