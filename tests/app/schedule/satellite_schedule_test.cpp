// The schedule over a real catalogue (docs/satellites.md "The schedule"): [[schedule]] read and
// refused as the schema says, and a plan whose every track sees its satellite up, switching at
// the pass search's own AOS and LOS.
#include "schedule/satellite_schedule.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "azt/orbit/satellite.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

std::vector<ScheduleEntryConfig> entries(const std::string& text) {
  return schedule_config_from(ConfigFile::parse(text, "test.toml"));
}

TEST(ScheduleConfig, EntriesInPriorityOrderWithTheirRules) {
  const auto e = entries(
      "[[schedule]]\nsat = \"NOAA 19\"\nmin_el_deg = 10\n"
      "[[schedule]]\nsat = \"25544\"\npreempt = \"finish\"\n");
  ASSERT_EQ(e.size(), 2U);
  EXPECT_EQ(e[0].sat, "NOAA 19");
  EXPECT_DOUBLE_EQ(e[0].min_el_deg, 10.0);
  EXPECT_EQ(e[0].preempt, schedule::Preempt::TakeOver);
  EXPECT_EQ(e[1].preempt, schedule::Preempt::Finish);
}

TEST(ScheduleConfig, AMissingOrRepeatedSatelliteOrAnUnknownRuleIsRefused) {
  EXPECT_THROW(entries("[[schedule]]\nmin_el_deg = 10\n"), UsageError);
  EXPECT_THROW(entries("[[schedule]]\nsat = \"ISS\"\n[[schedule]]\nsat = \"ISS\"\n"), UsageError);
  EXPECT_THROW(entries("[[schedule]]\nsat = \"ISS\"\npreempt = \"sometimes\"\n"), UsageError);
  EXPECT_THROW(entries("[[schedule]]\nsat = \"ISS\"\nmin_el_deg = 95\n"), UsageError);
}

class SatelliteSchedule : public ::testing::Test {
 protected:
  SatelliteCatalogue cat = SatelliteCatalogue::load(AZT_TEST_DATA_DIR "/omm/catalogue.tle");
  ScheduleSite site{astro::Observer{41.7, -72.7, 50.0}, 0.0, orbit::HorizonMask{}};
  astro::UtcInstant from = *astro::parse_iso8601_utc("2024-03-01T12:00:00Z");
  schedule::ScheduleRules rules;

  double seconds_after_from(const json& iso) const {
    return astro::parse_iso8601_utc(iso.get<std::string>())->unix_seconds() - from.unix_seconds();
  }
};

TEST_F(SatelliteSchedule, EveryTrackSeesItsSatelliteUpAndStartsAtAnAosOrASwitch) {
  const auto e = entries("[[schedule]]\nsat = \"NOAA 19\"\n[[schedule]]\nsat = \"ISS\"\n");
  const json plan = plan_satellite_schedule(cat, e, site, rules, from, 12.0, {180.0, 0.0});
  int tracks = 0;
  double previous_end_s = -1.0;
  for (const auto& s : plan["plan"]) {
    if (s["kind"] != "track") continue;
    ++tracks;
    const auto& sat = cat.find(s["sat"].get<std::string>());
    EXPECT_EQ(std::to_string(s["norad"].get<long>()), sat.elements.catalog);
    const double a = seconds_after_from(s["from"]);
    const double b = seconds_after_from(s["to"]);
    for (double t : {a + 1.0, 0.5 * (a + b), b - 1.0}) {
      const auto l = orbit::look(sat, astro::utc_plus(from, t), 0.0, site.site);
      ASSERT_TRUE(static_cast<bool>(l));
      EXPECT_GT(l->el_deg, 0.0) << s.dump() << " at +" << t << " s";
    }
    // A track begins at its pass's AOS (as the pass search finds it), or where the one before
    // it ended (a take-over, or the rest of a pass after one).
    const auto passes = orbit::find_satellite_passes(sat, from, 12.0, site.mask, 0.0, site.site);
    bool at_aos = false;
    for (const auto& p : passes.value()) at_aos = at_aos || std::fabs(p.aos_s - a) < 0.01;
    EXPECT_TRUE(at_aos || std::fabs(a - previous_end_s) < 0.01) << s.dump();
    previous_end_s = b;
  }
  EXPECT_GE(tracks, 6) << plan.dump();
}

}  // namespace
}  // namespace azt::app
