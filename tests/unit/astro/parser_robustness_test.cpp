// Every text parser facing users or files, fed seeded random and mutated input: it must answer
// (a value or an error with a message), never crash, hang or read out of bounds (run this under
// the asan-ubsan preset for the last part). A bounded version of fuzzing, in the test command.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/maidenhead.hpp"
#include "azt/astro/target.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/util/parse_number.hpp"

namespace azt::astro {
namespace {

constexpr int kRounds = 20000;

/// Random strings biased towards the characters the grammars use, plus mutations of valid input.
class InputGenerator {
 public:
  InputGenerator(std::uint64_t seed, std::vector<std::string> seeds)
      : rng_(seed), seeds_(std::move(seeds)) {}

  std::string next() {
    std::string s = coin(0.5) ? pick_seed() : std::string();
    const int edits = static_cast<int>(rng_() % 6);
    for (int i = 0; i < edits; ++i) mutate(s);
    return s;
  }

 private:
  bool coin(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  std::string pick_seed() { return seeds_[rng_() % seeds_.size()]; }
  char random_char() {
    static const std::string alphabet = "0123456789+-.:,TZtz eE#@nNaAiIfFxXrRradec\t\n\r";
    return coin(0.8) ? alphabet[rng_() % alphabet.size()] : static_cast<char>(rng_() % 256);
  }
  void mutate(std::string& s) {
    const std::size_t pos = s.empty() ? 0 : rng_() % (s.size() + 1);
    switch (rng_() % 4) {
      case 0:
        s.insert(pos, 1, random_char());
        break;
      case 1:
        if (pos < s.size()) s.erase(pos, 1);
        break;
      case 2:
        if (pos < s.size()) s[pos] = random_char();
        break;
      default:
        s.insert(pos, pick_seed().substr(0, rng_() % 12));
        break;
    }
  }

  std::mt19937_64 rng_;
  std::vector<std::string> seeds_;
};

/// Both paths must be exercised: some inputs accepted, most rejected.
constexpr int kMinAccepted = 100;

template <typename T>
void expect_answered(const Result<T>& r, const std::string& input) {
  if (!r.ok()) {
    EXPECT_FALSE(r.error().message.empty()) << input;
  }
}

TEST(ParserRobustness, Iso8601) {
  InputGenerator gen(
      1, {"2025-03-14T06:00:00Z", "1999-12-31 23:59:59.999+00:00", "2016-12-31T23:59:60Z"});
  int accepted = 0;
  for (int i = 0; i < kRounds; ++i) {
    const std::string s = gen.next();
    auto r = parse_iso8601_utc(s);
    accepted += r.ok() ? 1 : 0;
    expect_answered(r, s);
    if (r.ok()) {
      EXPECT_TRUE(parse_iso8601_utc(format_iso8601_utc(*r)).ok()) << s;
    }
  }
  EXPECT_GT(accepted, kMinAccepted);
}

TEST(ParserRobustness, Locators) {
  InputGenerator gen(2, {"FN06HE", "JO20", "RR99XX99XX", "aa00aa00aa"});
  int accepted = 0;
  for (int i = 0; i < kRounds; ++i) {
    const std::string s = gen.next();
    auto r = decode_locator(s);
    accepted += r.ok() ? 1 : 0;
    expect_answered(r, s);
    if (r.ok()) {
      EXPECT_LE(std::abs(r->lat_deg), 90.0) << s;
      EXPECT_LE(std::abs(r->lon_deg), 180.0) << s;
    }
  }
  EXPECT_GT(accepted, kMinAccepted);
}

TEST(ParserRobustness, Targets) {
  InputGenerator gen(3, {"moon", "radec:83.6,22.0", "Cassiopeia A", "sgr a*"});
  int accepted = 0;
  for (int i = 0; i < kRounds; ++i) {
    const std::string s = gen.next();
    auto r = parse_target(s);
    accepted += r.ok() ? 1 : 0;
    expect_answered(r, s);
  }
  EXPECT_GT(accepted, kMinAccepted);
}

TEST(ParserRobustness, Numbers) {
  InputGenerator gen(4, {"46.189", "-79.393", "1e-3", "+0.5"});
  for (int i = 0; i < kRounds; ++i) {
    const std::string s = gen.next();
    if (auto v = parse_finite_double(s)) {
      EXPECT_TRUE(std::isfinite(*v)) << s;
    }
  }
}

TEST(ParserRobustness, LeapSecondLists) {
  // First three steps of the IERS list (each changes TAI-UTC by exactly 1 s, as the parser
  // demands).
  const std::string valid =
      "#@\t3991593600\n2272060800\t10\t# 1 Jan 1972\n2287785600\t11\t# 1 Jul 1972\n"
      "2303683200\t12\t# 1 Jan 1973\n";
  ASSERT_TRUE(LeapSecondTable::parse_ietf_list(valid).ok());
  InputGenerator gen(5, {valid});
  int accepted = 0;
  for (int i = 0; i < kRounds / 4; ++i) {
    const std::string s = gen.next();
    auto r = LeapSecondTable::parse_ietf_list(s);
    accepted += r.ok() ? 1 : 0;
    expect_answered(r, s);
    if (r.ok()) {
      EXPECT_FALSE(r->steps().empty()) << s;
    }
  }
  EXPECT_GT(accepted, kMinAccepted);
}

}  // namespace
}  // namespace azt::astro
