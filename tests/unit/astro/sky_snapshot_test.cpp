// The sky at one instant (moved from the app to the core, errors as Results): the
// snapshot observes each target as the reduction chain does on its own, and adds what a DX
// station sees of the Moon only when there is one.
#include "azt/astro/sky_snapshot.hpp"

#include <gtest/gtest.h>

#include "azt/astro/erfa_ephemeris.hpp"

namespace azt::astro {
namespace {

constexpr double kArcsecDeg = 1.0 / 3600.0;

TimeScales oracle_time() {
  // ../shared/oracles/README.md §2: 2025-03-14 06:00:00 UTC, UT1 = UTC + 0.203387 s.
  const auto utc = UtcInstant::from_calendar(2025, 3, 14, 6, 0, 0.0);
  EXPECT_TRUE(utc.ok());
  return make_time_scales(*utc, 69.184 - 68.980613, LeapSecondTable::builtin()).value();
}

TEST(SkySnapshot, ObservesTheMoonAsTheOracleChainDoes) {
  const ErfaEphemeris eph;
  SkySite site;
  site.observer = Observer{46.189, -79.393, 300.0};
  site.atmosphere.model = RefractionModel::None;
  const auto sky = SkySnapshot::at(eph, site, oracle_time());
  ASSERT_TRUE(sky.ok()) << sky.error().message;
  const auto moon = sky->observe(Target::moon());
  ASSERT_TRUE(moon.ok()) << moon.error().message;
  EXPECT_NEAR(moon->observation.place.az_deg, 192.3769552, 0.02 * kArcsecDeg);
  EXPECT_NEAR(moon->observation.place.el_geometric_deg, 45.4544030, 0.02 * kArcsecDeg);
  EXPECT_FALSE(moon->dx_range_rate_km_s.has_value()) << "a DX figure without a DX station";
  EXPECT_NEAR(sky->time().dut1_s, 0.203387, 1e-9);
}

TEST(SkySnapshot, TheDxStationSeesTheMoonFromItsOwnPlace) {
  const ErfaEphemeris eph;
  SkySite site;
  site.observer = Observer{46.189, -79.393, 300.0};
  site.dx = Observer{-33.9, 18.4, 0.0};  // Cape Town: the Moon is low or set there
  const auto sky = SkySnapshot::at(eph, site, oracle_time());
  ASSERT_TRUE(sky.ok());
  const auto moon = sky->observe(Target::moon());
  ASSERT_TRUE(moon.ok());
  ASSERT_TRUE(moon->dx_range_rate_km_s.has_value());
  ASSERT_TRUE(moon->dx_place.has_value());
  EXPECT_GT(std::abs(moon->dx_place->el_geometric_deg - moon->observation.place.el_geometric_deg),
            10.0);
  const auto sun = sky->observe(Target::sun());
  ASSERT_TRUE(sun.ok());
  EXPECT_FALSE(sun->dx_place.has_value()) << "DX figures are the Moon's alone";
}

TEST(SkySnapshot, AMinuteLaterIsTheSameStationAMinuteOn) {
  const ErfaEphemeris eph;
  SkySite site;
  site.observer = Observer{46.189, -79.393, 300.0};
  const auto now = SkySnapshot::at(eph, site, oracle_time());
  ASSERT_TRUE(now.ok());
  const auto later = now->later(60.0);
  ASSERT_TRUE(later.ok());
  EXPECT_NEAR((later->time().utc.mjd() - now->time().utc.mjd()) * 86400.0, 60.0, 1e-6);
  const JulianDate& t0 = now->time().tt;
  const JulianDate& t1 = later->time().tt;
  EXPECT_NEAR(((t1.jd1 - t0.jd1) + (t1.jd2 - t0.jd2)) * 86400.0, 60.0, 1e-6);
  EXPECT_DOUBLE_EQ(later->time().dut1_s, now->time().dut1_s);
  // The same as a snapshot built for that instant from scratch.
  const auto direct =
      SkySnapshot::at(eph, site,
                      *make_time_scales(utc_plus(oracle_time().utc, 60.0), oracle_time().dut1_s,
                                        LeapSecondTable::builtin()));
  const auto a = later->observe(Target::moon());
  const auto b = direct->observe(Target::moon());
  EXPECT_NEAR(a->observation.place.az_deg, b->observation.place.az_deg, 1e-9);
  EXPECT_NEAR(a->observation.place.el_geometric_deg, b->observation.place.el_geometric_deg, 1e-9);
  // The Moon has moved: a quarter of a degree of azimuth a minute at most here.
  const auto m0 = now->observe(Target::moon());
  EXPECT_GT(std::abs(a->observation.place.az_deg - m0->observation.place.az_deg), 0.01);
}

}  // namespace
}  // namespace azt::astro
