// A spacecraft from a JPL Horizons vector table (docs/satellites.md), observed through the same
// chain as the Moon. The check: a table of the Moon's own geocentric states (from eraMoon98, as the
// ERFA ephemeris, tests/data/horizons/make_fixtures.py) observed as a "spacecraft" must give the
// Moon's place — the table's light time, aberration and parallax are the Moon's.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "azt/astro/erfa_ephemeris.hpp"
#include "azt/astro/horizons.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/target.hpp"

namespace azt::astro {
namespace {

constexpr double kArcsec = 1.0 / 3600.0;

std::shared_ptr<const SpacecraftTable> moon_table() {
  std::ifstream in(std::string(AZT_TEST_DATA_DIR) + "/horizons/moon_vectors_csv_kms.txt");
  std::stringstream text;
  text << in.rdbuf();
  auto table = SpacecraftTable::parse_horizons_vectors(text.str());
  EXPECT_TRUE(table.ok()) << (table.ok() ? "" : table.error().message);
  return std::make_shared<const SpacecraftTable>(std::move(table).value());
}

TEST(SpacecraftTarget, AMoonTableIsObservedWhereTheMoonIs) {
  const auto table = moon_table();
  const Target craft = Target::spacecraft("Moon table", table, "a test body", 8420.0);
  const ErfaEphemeris eph;
  const auto airless = Atmosphere::make(0.0, 15.0, 0.0, RefractionModel::None).value();
  double worst_arcsec = 0.0;
  double worst_range_m = 0.0;
  for (int minute = 30; minute < 24 * 60 - 30; minute += 37) {  // inside the table's day
    const auto utc = UtcInstant::from_calendar(2025, 3, 1, minute / 60, minute % 60, 7.25).value();
    const auto t = make_time_scales(utc, 0.1, LeapSecondTable::builtin()).value();
    const Epoch epoch = make_epoch(eph, t).value();
    const Station st = make_station(epoch, Observer{46.189, -79.393, 300.0});
    const auto moon = observe(Target::moon(), eph, epoch, st, airless);
    const auto seen = observe(craft, eph, epoch, st, airless);
    ASSERT_TRUE(moon.ok() && seen.ok()) << (seen.ok() ? "" : seen.error().message);
    const double daz = std::remainder(seen->place.az_deg - moon->place.az_deg, 360.0) *
                       std::cos(moon->place.el_geometric_deg * M_PI / 180.0);
    const double del = seen->place.el_geometric_deg - moon->place.el_geometric_deg;
    worst_arcsec = std::max({worst_arcsec, std::fabs(daz) / kArcsec, std::fabs(del) / kArcsec});
    worst_range_m = std::max(worst_range_m,
                             std::fabs(*seen->place.distance_km - *moon->place.distance_km) * 1e3);
    EXPECT_NEAR(*seen->place.range_rate_km_s, *moon->place.range_rate_km_s, 1e-4);
  }
  std::printf("[ craft    ] Moon as a tabulated body: worst %.4f\" and %.2f m\n", worst_arcsec,
              worst_range_m);
  EXPECT_LT(worst_arcsec, 0.01);
  EXPECT_LT(worst_range_m, 5.0);
  EXPECT_EQ(craft.description, "a test body");
  EXPECT_DOUBLE_EQ(craft.frequency_mhz, 8420.0);
}

TEST(SpacecraftTarget, OutsideTheTableIsAnErrorNamingTheCraft) {
  const Target craft = Target::spacecraft("Probe", moon_table(), "", 0.0);
  const ErfaEphemeris eph;
  const auto airless = Atmosphere::make(0.0, 15.0, 0.0, RefractionModel::None).value();
  const auto utc = UtcInstant::from_calendar(2025, 3, 5, 0, 0, 0.0).value();
  const Epoch epoch =
      make_epoch(eph, make_time_scales(utc, 0.0, LeapSecondTable::builtin()).value()).value();
  const Station st = make_station(epoch, Observer{46.189, -79.393, 300.0});
  const auto seen = observe(craft, eph, epoch, st, airless);
  ASSERT_FALSE(seen.ok());
  EXPECT_NE(seen.error().message.find("Probe"), std::string::npos) << seen.error().message;
}

}  // namespace
}  // namespace azt::astro
