// One satellite from a station (moved from the app to the core): its look angles
// are SGP4's state turned by UT1, its element age counts from the epoch, and a decayed orbit is
// an error naming the satellite, never a position.
#include "azt/orbit/satellite.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "azt/orbit/tle.hpp"

namespace azt::orbit {
namespace {

constexpr std::string_view kIss1 =
    "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
constexpr std::string_view kIss2 =
    "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";

Satellite iss() {
  const auto e = parse_tle(kIss1, kIss2, "ISS (ZARYA)");
  EXPECT_TRUE(e.ok());
  auto sgp4 = Sgp4::make(*e);
  EXPECT_TRUE(sgp4.ok());
  return Satellite{*e, std::move(sgp4).value()};
}

astro::UtcInstant epoch_of(const Elements& e) {
  return astro::UtcInstant{astro::JulianDate{e.epoch_jd, e.epoch_jd_frac}};
}

TEST(Satellite, ElementAgeCountsFromTheEpoch) {
  const Satellite sat = iss();
  const astro::UtcInstant epoch = epoch_of(sat.elements);
  EXPECT_NEAR(element_age_days(sat.elements, epoch), 0.0, 1e-12);
  EXPECT_NEAR(element_age_days(sat.elements, astro::utc_plus(epoch, 3.5 * 86400.0)), 3.5, 1e-9);
  EXPECT_NEAR(element_age_days(sat.elements, astro::utc_plus(epoch, -86400.0)), -1.0, 1e-9);
}

TEST(Satellite, LookIsTheStateTurnedByUt1) {
  const Satellite sat = iss();
  const astro::UtcInstant t = astro::utc_plus(epoch_of(sat.elements), 600.0);
  const astro::Observer site{46.189, -79.393, 300.0};
  const auto l = look(sat, t, 0.2, site);
  ASSERT_TRUE(l.ok()) << l.error().message;
  const auto state = sat.sgp4.at_jd(t.jd.jd1, t.jd.jd2);
  ASSERT_TRUE(state.ok());
  const auto direct = look_angles(state->r_km, state->v_km_s,
                                  astro::JulianDate{t.jd.jd1, t.jd.jd2 + 0.2 / 86400.0}, site);
  EXPECT_DOUBLE_EQ(l->az_deg, direct.az_deg);
  EXPECT_DOUBLE_EQ(l->el_deg, direct.el_deg);
  // DUT1 matters: 0.8 s of Earth rotation moves a LEO's azimuth measurably.
  const auto other = look(sat, t, -0.6, site);
  ASSERT_TRUE(other.ok());
  EXPECT_GT(std::fabs(other->az_deg - l->az_deg) + std::fabs(other->el_deg - l->el_deg), 1e-4);
}

TEST(Satellite, ADecayedOrbitIsAnErrorNamingTheSatellite) {
  // The ISS's elements with a drag term (B* = 0.5) that brings it down within days.
  std::string line1(kIss1);
  line1.replace(53, 8, " 50000-0");
  line1[68] = static_cast<char>('0' + tle_checksum(line1));
  const auto e = parse_tle(line1, kIss2, "FALLING");
  ASSERT_TRUE(e.ok()) << e.error().message;
  auto sgp4 = Sgp4::make(*e);
  ASSERT_TRUE(sgp4.ok()) << sgp4.error().message;
  const Satellite sat{*e, std::move(sgp4).value()};
  std::optional<Error> decayed;
  for (int day = 0; day <= 60 && !decayed; ++day) {
    const auto l = look(sat, astro::utc_plus(epoch_of(sat.elements), day * 86400.0), 0.0,
                        astro::Observer{0.0, 0.0, 0.0});
    if (!l) decayed = l.error();
  }
  ASSERT_TRUE(decayed.has_value()) << "still in orbit after 60 days with B* = 0.5";
  EXPECT_EQ(decayed->message.rfind("FALLING: ", 0), 0U) << decayed->message;
}

}  // namespace
}  // namespace azt::orbit
