// Observer::make: range and finiteness checks on a WGS84 station.
// The worked station is the oracle README's site (/work/shared/oracles/README.md): 46.189 N,
// 79.393 W, 300 m, which is also the seed document's FN06HE station.

#include "azt/astro/observer.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>

namespace {

using azt::astro::Observer;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

TEST(Observer, KeepsTheOracleSite) {
  const auto o = Observer::make(46.189, -79.393, 300.0);
  ASSERT_TRUE(o.ok()) << o.error().message;
  EXPECT_EQ(o->lat_deg, 46.189);
  EXPECT_EQ(o->lon_deg, -79.393);  // west is negative
  EXPECT_EQ(o->height_m, 300.0);
}

TEST(Observer, AcceptsTheClosedRangeEnds) {
  EXPECT_TRUE(Observer::make(90.0, 180.0, 10000.0).ok());
  EXPECT_TRUE(Observer::make(-90.0, -180.0, -500.0).ok());
  EXPECT_TRUE(Observer::make(0.0, 0.0, 0.0).ok());
  EXPECT_TRUE(Observer::make(31.5, 35.5, -430.0).ok());      // Dead Sea shore
  EXPECT_TRUE(Observer::make(27.988, 86.925, 8849.0).ok());  // Everest summit
}

void expect_error(double lat, double lon, double h, const std::string& field,
                  const std::string& range) {
  const auto o = Observer::make(lat, lon, h);
  ASSERT_FALSE(o.ok()) << field;
  EXPECT_TRUE(contains(o.error().message, field)) << o.error().message;
  EXPECT_TRUE(contains(o.error().message, range)) << o.error().message;
}

TEST(Observer, NamesTheFieldAndRangeOfABadValue) {
  expect_error(90.0001, 0.0, 0.0, "latitude", "[-90, 90] deg");
  expect_error(-91.0, 0.0, 0.0, "latitude", "[-90, 90] deg");
  expect_error(0.0, 180.5, 0.0, "longitude", "[-180, 180] deg");
  expect_error(0.0, -360.0, 0.0, "longitude", "[-180, 180] deg");
  expect_error(0.0, 0.0, 10000.5, "height", "[-500, 10000] m");
  expect_error(0.0, 0.0, -501.0, "height", "[-500, 10000] m");
}

TEST(Observer, RejectsNonFiniteValues) {
  expect_error(kNan, 0.0, 0.0, "latitude", "finite");
  expect_error(0.0, kInf, 0.0, "longitude", "finite");
  expect_error(0.0, -kInf, 0.0, "longitude", "finite");
  expect_error(0.0, 0.0, kNan, "height", "finite");
}

TEST(Observer, TheMessageGivesTheBadValue) {
  const auto o = Observer::make(123.5, 0.0, 0.0);
  ASSERT_FALSE(o.ok());
  EXPECT_TRUE(contains(o.error().message, "123.5")) << o.error().message;
}

// Property: inside the box every station is accepted unchanged; just outside, rejected.
TEST(Observer, RandomStationsInsideAreKeptOutsideRejected) {
  std::mt19937_64 rng(0x0b5e7);
  std::uniform_real_distribution<double> lat(-90.0, 90.0), lon(-180.0, 180.0), h(-500.0, 10000.0);
  std::uniform_real_distribution<double> excess(1e-9, 1000.0);
  for (int i = 0; i < 5000; ++i) {
    const double la = lat(rng), lo = lon(rng), hm = h(rng);
    const auto o = Observer::make(la, lo, hm);
    ASSERT_TRUE(o.ok()) << o.error().message;
    EXPECT_EQ(o->lat_deg, la);
    EXPECT_EQ(o->lon_deg, lo);
    EXPECT_EQ(o->height_m, hm);
    const double e = excess(rng);
    EXPECT_FALSE(Observer::make(90.0 + e, lo, hm).ok());
    EXPECT_FALSE(Observer::make(-90.0 - e, lo, hm).ok());
    EXPECT_FALSE(Observer::make(la, 180.0 + e, hm).ok());
    EXPECT_FALSE(Observer::make(la, -180.0 - e, hm).ok());
    EXPECT_FALSE(Observer::make(la, lo, 10000.0 + e).ok());
    EXPECT_FALSE(Observer::make(la, lo, -500.0 - e).ok());
  }
}

}  // namespace
