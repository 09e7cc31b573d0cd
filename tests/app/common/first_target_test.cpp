// What a first start tracks: the Moon when it is up, else the Sun, else a radio source at least
// 20° up, else the Moon waiting for moonrise. Instants of each case are found hour by hour over
// a fortnight at FN06HE, and the choice checked against the elevations the sky engine gives.
#include "common/first_target.hpp"

#include <gtest/gtest.h>

#include <optional>

#include "azt/astro/erfa_ephemeris.hpp"
#include "common/sky_report.hpp"
#include "config/config_file.hpp"
#include "config/sky_config.hpp"

namespace azt::app {
namespace {

constexpr double kFrom = 1767225600.0;  // 2026-01-01 00:00 UTC

class FirstTargetTest : public ::testing::Test {
 protected:
  astro::SkySnapshot sky_at(double unix_s) const {
    return sky_snapshot(ephemeris_, sky_.settings, astro::UtcInstant::from_unix_seconds(unix_s))
        .value();
  }
  double el_deg(const astro::SkySnapshot& sky, const astro::Target& t) const {
    return sky.observe(t).value().observation.el_deg;
  }
  /// The first hour of the fortnight where `when` holds.
  template <typename When>
  std::optional<astro::SkySnapshot> find(When when) const {
    for (double t = kFrom; t < kFrom + 14 * 86400.0; t += 3600.0) {
      auto sky = sky_at(t);
      if (when(sky)) return sky;
    }
    return std::nullopt;
  }

  astro::ErfaEphemeris ephemeris_;
  SkyConfig sky_ = sky_config_from(ConfigFile::parse("[station]\ngrid = \"FN06HE\"\n", "t.toml"));
};

TEST_F(FirstTargetTest, TheMoonWhenItIsUp) {
  const auto sky = find([&](const auto& s) { return el_deg(s, astro::Target::moon()) > 10.0; });
  ASSERT_TRUE(sky);
  const FirstTarget first = choose_first_target(*sky, sky_.targets, 0.0);
  EXPECT_EQ(first.name, "moon");
  EXPECT_NE(first.why.find("the Moon is up"), std::string::npos) << first.why;
}

TEST_F(FirstTargetTest, TheSunWhenTheMoonIsDown) {
  const auto sky = find([&](const auto& s) {
    return el_deg(s, astro::Target::moon()) < -5.0 && el_deg(s, astro::Target::sun()) > 5.0;
  });
  ASSERT_TRUE(sky);
  const FirstTarget first = choose_first_target(*sky, sky_.targets, 0.0);
  EXPECT_EQ(first.name, "sun");
  EXPECT_NE(first.why.find("the Moon is below the horizon"), std::string::npos) << first.why;
}

TEST_F(FirstTargetTest, ARadioSourceHighEnoughAtNightWithoutTheMoon) {
  const auto sky = find([&](const auto& s) {
    return el_deg(s, astro::Target::moon()) < -5.0 && el_deg(s, astro::Target::sun()) < -5.0;
  });
  ASSERT_TRUE(sky);
  const FirstTarget first = choose_first_target(*sky, sky_.targets, 0.0);
  const astro::Target* chosen = nullptr;
  for (const auto& t : sky_.targets) {
    if (t.name == first.name) chosen = &t;
  }
  ASSERT_NE(chosen, nullptr) << first.name;
  EXPECT_EQ(chosen->kind, astro::Target::Kind::Source);
  EXPECT_GE(el_deg(*sky, *chosen), kSourceMinElDeg);
  // The first in the catalogue's order: none listed before it was high enough.
  for (const auto& t : sky_.targets) {
    if (&t == chosen) break;
    if (t.kind == astro::Target::Kind::Source) {
      EXPECT_LT(el_deg(*sky, t), kSourceMinElDeg) << t.name;
    }
  }
}

TEST_F(FirstTargetTest, TheMoonWaitingWhenNothingClearsTheLimit) {
  const auto sky = find([&](const auto& s) { return el_deg(s, astro::Target::moon()) < -5.0; });
  ASSERT_TRUE(sky);
  // A limit above everything (the horizon behind a hill): nothing qualifies.
  const FirstTarget first = choose_first_target(*sky, sky_.targets, 89.9);
  EXPECT_EQ(first.name, "moon");
  EXPECT_NE(first.why.find("waiting for moonrise"), std::string::npos) << first.why;
}

}  // namespace
}  // namespace azt::app
