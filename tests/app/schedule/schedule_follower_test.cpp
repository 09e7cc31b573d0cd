// The daemon's follower of the satellite schedule (docs/satellites.md "The schedule") over the
// station's own front door, satellite tracker and motor power relay: it carries out the plan it
// shows, step by step — the satellite followed from its pre-position, a STOP after the LOS, park
// slot 1 after the idle time, the power off once parked and on before the next pre-position —
// tells the hooks each moment, and steps aside for any other command until resumed. The time is
// injected; the antenna stands where it is put.
#include "schedule/schedule_follower.hpp"

#include <gtest/gtest.h>

#include "azt/astro/erfa_ephemeris.hpp"
#include "config/config_file.hpp"
#include "support/station_rig.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

constexpr double kStartUnixS = 1709294400.0;  // 2024-03-01 12:00 UTC, by the ISS's epoch
const astro::Observer kFn06{46.18958, -79.39375, 301.0};

double unix_of(const json& iso) {
  return astro::parse_iso8601_utc(iso.get<std::string>())->unix_seconds();
}

struct FollowerRig {
  DaemonConfig config = [] {
    DaemonConfig c;
    c.sky.settings.observer = kFn06;
    return c;
  }();
  astro::ErfaEphemeris ephemeris;
  SkyFollower sky{ephemeris, config.sky};
  control::ModeController modes{config.park, config.out_of_range, config.station.el_range.min_deg};
  testing::StandingAntenna antenna;
  double unix_s = kStartUnixS;
  SatelliteTracker satellites = [this] {
    SatelliteSettings s;
    s.site = kFn06;
    SatelliteTracker t(s, [](const std::string&) {});
    t.adopt(SatelliteCatalogue::load(AZT_TEST_DATA_DIR "/sat/iss_2024.tle"), unix_s);
    return t;
  }();
  std::vector<std::string> accepted;
  StationCommands commands{StationCommandParts{
      modes, antenna, sky, &satellites, config.target_limits(), config.station.el_range,
      [this] { return unix_s; }, [this] { return unix_s; }, 0.0,
      [this](const CommandSource& source, const CommandRecord& record) {
        accepted.push_back(source.name + ": " + record.words);
        if (follower) follower->on_command(source);
      },
      [](const CommandSource&, const Refusal&) {}}};
  MotorPower power{simulated_output({"sim", 1, false, "[hardware.power] relay"}), 2.0,
                   [](const std::string&) {}};
  std::vector<std::string> events;
  std::unique_ptr<ScheduleFollower> follower;

  FollowerRig() {
    schedule::ScheduleRules rules;
    rules.idle_park_s = 60.0;
    rules.power_on_lead_s = 3.0;
    follower = std::make_unique<ScheduleFollower>(
        ScheduleFollowerParts{
            commands, satellites, &power, run_inline, [this] { return unix_s; },
            [this] { return unix_s; },
            [this] {
              return control::AzEl{antenna.az_deg, antenna.el_deg};
            },
            [] { return true; },
            [this](HookEvent e, const schedule::Priority* sat, const PlannedPass* pass) {
              std::string line(hook_event_name(e));
              if (sat != nullptr) line += " " + sat->norad;
              if (pass != nullptr) line += " max " + std::to_string(pass->max_el_deg);
              events.push_back(line);
            },
            [](const std::string&) {}},
        std::vector<ScheduleEntryConfig>{{"ISS", 0.0, schedule::Preempt::TakeOver}},
        ScheduleSite{kFn06, 0.0, {}}, rules);
  }
  /// Ticks at `t`, the plan made at the first tick.
  void at(double t) {
    unix_s = t;
    follower->tick();
  }
  /// The plan's first step of `kind` after `after`.
  json step(const std::string& kind, double after = 0.0) {
    const json view = follower->plan_view();
    for (const auto& s : view["plan"]) {
      if (s["kind"] == kind && unix_of(s["from"]) > after) return s;
    }
    return nullptr;
  }
};

double mid(const json& step) { return (unix_of(step["from"]) + unix_of(step["to"])) / 2.0; }

TEST(ScheduleFollower, CarriesOutThePlanItShowsStepByStep) {
  FollowerRig rig;
  rig.at(kStartUnixS);
  const json pre = rig.step("preposition");
  ASSERT_FALSE(pre.is_null()) << rig.follower->plan_view().dump();
  // Idle from the start: parked after a minute, then the power off once the antenna stands.
  const json park = rig.step("park");
  ASSERT_FALSE(park.is_null());
  EXPECT_NEAR(unix_of(park["from"]), kStartUnixS + 60.0, 0.01);
  rig.at(mid(park));
  EXPECT_EQ(rig.modes.mode(), control::Mode::Park);
  rig.at(mid(rig.step("power_off")));
  EXPECT_FALSE(rig.power.on());
  // Before the pre-position the power comes on, its lead ahead.
  rig.at(unix_of(pre["from"]) - 1.0);
  EXPECT_TRUE(rig.power.on());
  rig.at(mid(pre));
  EXPECT_TRUE(rig.commands.tracking_satellite());
  EXPECT_EQ(rig.commands.commander(), "schedule");
  const json track = rig.step("track");
  rig.at(mid(track));
  EXPECT_TRUE(rig.commands.tracking_satellite());
  // After the LOS the antenna waits where it is instead of swinging to the next AOS.
  rig.at(unix_of(track["to"]) + 1.0);
  EXPECT_EQ(rig.modes.mode(), control::Mode::Stop);
  ASSERT_GE(rig.events.size(), 4U);
  EXPECT_EQ(rig.events[0], "park");
  EXPECT_EQ(rig.events[1].rfind("pre_position 25544 max ", 0), 0U) << rig.events[1];
  EXPECT_EQ(rig.events[2].rfind("aos 25544", 0), 0U) << rig.events[2];
  EXPECT_EQ(rig.events[3].rfind("los 25544", 0), 0U) << rig.events[3];
}

TEST(ScheduleFollower, AnotherCommandHoldsItUntilResumed) {
  FollowerRig rig;
  rig.at(kStartUnixS);
  const json pre = rig.step("preposition");
  (void)rig.commands.point(CommandSource{CommandSource::Kind::Console, "console 10.0.0.2"},
                           PositionTarget{90.0, 30.0});
  EXPECT_EQ(rig.follower->state()["held_by"], "console 10.0.0.2");
  EXPECT_TRUE(rig.power.on());  // a person took the antenna: its motors are powered
  rig.at(mid(pre));
  EXPECT_FALSE(rig.commands.tracking_satellite());
  EXPECT_EQ(rig.modes.mode(), control::Mode::Manual);
  ASSERT_TRUE(rig.follower->resume("console 10.0.0.2"));
  rig.at(mid(pre) + 0.5);  // planned again from where the operator left the antenna
  rig.at(mid(rig.step("preposition", mid(pre) - 600.0)));
  EXPECT_TRUE(rig.commands.tracking_satellite());
  EXPECT_EQ(rig.commands.commander(), "schedule");
  EXPECT_EQ(rig.follower->state()["running"], true);
}

TEST(ScheduleFollower, ASatelliteTheCatalogueLacksIsAProblemShownNotAFailure) {
  FollowerRig rig;
  rig.follower->set_entries({{"NO SUCH BIRD", 0.0, schedule::Preempt::TakeOver},
                             {"ISS", 0.0, schedule::Preempt::TakeOver}});
  rig.at(kStartUnixS);
  const json state = rig.follower->state();
  ASSERT_EQ(state["problems"].size(), 1U);
  EXPECT_NE(state["problems"][0].get<std::string>().find("NO SUCH BIRD"), std::string::npos);
  EXPECT_FALSE(rig.step("track").is_null());
}

TEST(ScheduleFollower, AnEmptyListLeavesTheStationAloneAndPowered) {
  FollowerRig rig;
  rig.at(kStartUnixS);
  rig.at(mid(rig.step("power_off")));
  EXPECT_FALSE(rig.power.on());
  rig.follower->set_entries({});
  EXPECT_TRUE(rig.power.on());
  EXPECT_TRUE(rig.follower->state().is_null());
  const auto before = rig.accepted.size();
  rig.at(kStartUnixS + 3600.0);
  EXPECT_EQ(rig.accepted.size(), before);
}

}  // namespace
}  // namespace azt::app
