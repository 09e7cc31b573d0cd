// The console over the daemon's own parts (docs/web-api.md): what /api/state says of the holder and
// the target (console_state.cpp), the live actions (daemon_console.cpp) and a setting saved to the
// file and applied or left for a restart (console_settings.cpp). The antenna stands still unless a
// direction test drives it; saves run inline.
#include "console/daemon_console.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "azt/astro/erfa_ephemeris.hpp"
#include "support/station_rig.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

fs::path station_file() {
  const fs::path dir =
      fs::temp_directory_path() / ("azt-daemon-console-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "azeltrack.toml") << "# the operator's own note\nschema_version = 2\n"
                                           "[station]\ngrid = \"FN20\"\n[target]\nname = \"stop\"\n"
                                           "[log]\nlevel = \"info\"\n";
  return dir / "azeltrack.toml";
}

std::string read(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str();
}

struct ConsoleRig {
  fs::path file = station_file();
  ConfigStore store = ConfigStore::open(file.string());
  DaemonConfig config = store.config();
  astro::ErfaEphemeris ephemeris;
  SkyFollower sky{ephemeris, config.sky};
  control::ModeController modes{config.park, config.out_of_range, config.station.el_range.min_deg};
  testing::StandingAntenna antenna;
  double now_s = 0.0;
  StationCommands commands{StationCommandParts{
      modes, antenna, sky, nullptr, config.target_limits(), config.station.el_range,
      [this] { return now_s; }, [] { return 1.8e9; }, 0.0,
      [this](const CommandSource&, const CommandRecord&) { test.interrupt("another command"); },
      [](const CommandSource&, const Refusal&) {}}};
  DirectionTest test{
      DirectionTestParts{antenna, commands, modes, [] { return false; }, [this] { return now_s; }}};
  DaemonConsole console{ConsoleParts{config,
                                     store,
                                     ephemeris,
                                     sky,
                                     modes,
                                     commands,
                                     antenna,
                                     nullptr,
                                     [this] { return now_s; },
                                     [] { return 1.8e9; },
                                     json::object(),
                                     [] {
                                       return json{{"estop", "released"}};
                                     },
                                     run_inline,
                                     nullptr,
                                     nullptr,
                                     [](const std::string&) {},
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     &test,
                                     nullptr,
                                     nullptr}};

  ~ConsoleRig() { fs::remove_all(file.parent_path()); }

  /// act() answered at once or after `ticks` of 0.1 s of the loop (a direction test).
  ActResult act(const std::string& action, const json& body, int ticks = 0) {
    std::optional<ActResult> got;
    console.act(action, body, "console 127.0.0.1", [&](ActResult r) { got = std::move(r); });
    for (int i = 0; i < ticks && !got; ++i) {
      now_s += 0.1;
      antenna.tick(now_s, test.demand(now_s).value_or(modes.demand(std::nullopt)), {});
      test.tick(now_s);
    }
    if (!got) ADD_FAILURE() << action << " not answered";
    return got.value_or(ActResult{});
  }
};

TEST(DaemonConsole, TheStateNamesWhoHoldsTheAntenna) {
  ConsoleRig rig;
  rig.act("stop", json::object());
  json s = rig.console.state();
  EXPECT_EQ(s["mode"], "STOP");
  EXPECT_EQ(s["control"]["holder"], "console");
  EXPECT_EQ(s["control"]["pc_allowed"], false);
  EXPECT_EQ(s["pc_locked_out"], true);
  EXPECT_TRUE(s["antenna"]["known"]);
  EXPECT_DOUBLE_EQ(s["antenna"]["az_deg"].get<double>(), 100.0);
  EXPECT_TRUE(s["error_deg"].is_null()) << "no target, no pointing error";

  const ActResult pc = rig.act("control/pc", json::object());
  EXPECT_EQ(pc.fields["mode"], "EXT");
  EXPECT_EQ(pc.fields["control"]["pc_allowed"], true);
  EXPECT_DOUBLE_EQ(rig.antenna.az_deg, 100.0) << "allowing PC control moves nothing";
  EXPECT_EQ(rig.console.state()["pc_locked_out"], false);
}

TEST(DaemonConsole, AManualTargetIsShownWithItsPointingError) {
  ConsoleRig rig;
  const ActResult r = rig.act("target", json{{"az_deg", 130.0}, {"el_deg", 25.0}});
  ASSERT_FALSE(r.error.has_value()) << r.error->what();
  const json s = rig.console.state();
  EXPECT_EQ(s["mode"], "MAN");
  EXPECT_NEAR(s["error_deg"]["az"].get<double>(), 30.0, 1e-9);
  EXPECT_NEAR(s["error_deg"]["el"].get<double>(), 5.0, 1e-9);
}

TEST(DaemonConsole, ASettingIsSavedWithTheFileKeptAndListedForARestartOrApplied) {
  ConsoleRig rig;
  const ActResult r = rig.act("config/log", json{{"level", "warn"}});
  ASSERT_FALSE(r.error.has_value()) << r.error->what();
  const std::string text = read(rig.file);
  EXPECT_NE(text.find("level = \"warn\""), std::string::npos) << text;
  EXPECT_NE(text.find("# the operator's own note"), std::string::npos) << "comments kept: " << text;
  EXPECT_EQ(ConfigStore::open(rig.file.string()).root()["log"]["level"].value_or(std::string()),
            "warn");
  const json listed = r.fields.value("applied", json::array());
  const json waiting = r.fields.value("restart_needed", json::array());
  EXPECT_EQ(listed.size() + waiting.size(), 1U) << r.fields.dump();
}

TEST(DaemonConsole, AnInvalidSettingIsRefusedNamingItsFieldAndNothingIsSaved) {
  ConsoleRig rig;
  const std::string before = read(rig.file);
  try {
    rig.act("config/log", json{{"level", "loud"}});
    ADD_FAILURE() << "accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 400U);
    EXPECT_EQ(e.field(), "level");
  }
  EXPECT_EQ(read(rig.file), before);
}

TEST(DaemonConsole, TheDirectionTestAnswersWhenTheAxisHasMoved) {
  ConsoleRig rig;
  rig.antenna.test_step_deg = 0.05;
  const ActResult r = rig.act("hardware/direction-test", json{{"axis", "az"}}, 30);
  ASSERT_FALSE(r.error.has_value()) << r.error->what();
  EXPECT_EQ(r.fields["verdict"], "ok");
  EXPECT_EQ(r.fields["commanded"], "cw");
  EXPECT_THROW(rig.act("hardware/direction-test", json{{"axis", "pol"}}), ApiError);
}

TEST(DaemonConsole, TheDirectionTestIsRefusedWhileTracking) {
  ConsoleRig rig;
  ASSERT_FALSE(rig.act("target", json{{"name", "sun"}}).error.has_value());
  try {
    rig.act("hardware/direction-test", json{{"axis", "el"}});
    ADD_FAILURE() << "accepted while tracking";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 409U);
    EXPECT_NE(std::string(e.what()).find("tracking"), std::string::npos);
  }
}

TEST(DaemonConsole, TheStateShowsEachAxisBrakeMotorAndHoming) {
  ConsoleRig rig;
  EXPECT_FALSE(rig.console.state()["antenna"].contains("axes")) << "nothing to show: no key";
  control::AxisStatus az;
  az.brake = control::BrakeState::Released;
  az.brake_release = true;
  az.current_a = 2.5;
  az.temperature_c = 41.0;
  az.homing = control::HomingState::Seeking;
  az.held = "not homed: homing in progress (seeking the home switch)";
  az.pulse_count = -17;
  control::AxisStatus pol;  // a pulse-counted feed, homed
  pol.homing = control::HomingState::Homed;
  pol.pulse_count = 180;
  rig.antenna.axes_ = {{"az", az}, {"el", control::AxisStatus{}}, {"pol", pol}};
  const json axes = rig.console.state()["antenna"]["axes"];
  EXPECT_EQ(axes["az"]["brake"], "released");
  EXPECT_EQ(axes["az"]["brake_released"], true);
  EXPECT_EQ(axes["az"]["current_a"], 2.5);
  EXPECT_EQ(axes["az"]["temperature_c"], 41.0);
  EXPECT_EQ(axes["az"]["homing"], "seeking");
  EXPECT_EQ(axes["az"]["held"], az.held);
  EXPECT_EQ(axes["az"]["pulse_count"], -17);
  EXPECT_FALSE(axes.contains("el")) << "a plain axis has nothing more to show";
  EXPECT_EQ(axes["pol"]["homing"], "homed");
  EXPECT_EQ(axes["pol"]["held"], nullptr);
  EXPECT_EQ(axes["pol"]["pulse_count"], 180);
}

TEST(DaemonConsole, HomingIsAskedOfThePulseAxisAndEndedByAStop) {
  ConsoleRig rig;
  const ActResult r = rig.act("hardware/home", json{{"axis", "el"}});
  ASSERT_FALSE(r.error.has_value());
  EXPECT_EQ(rig.antenna.homed, std::vector<std::string>{"el"});
  const auto status_of = [&rig](const json& body) {
    try {
      rig.act("hardware/home", body);
    } catch (const ApiError& e) {
      return e.status();
    }
    return 200U;
  };
  // The pol axis is asked as az and el are; whether it counts pulses is the station's to say.
  EXPECT_EQ(status_of(json{{"axis", "pol"}}), 200U);
  EXPECT_EQ(rig.antenna.homed, (std::vector<std::string>{"el", "pol"}));
  EXPECT_EQ(status_of(json{{"axis", "feed"}}), 400U);
  EXPECT_EQ(status_of(json::object()), 400U);
  rig.antenna.home_refusal = "the axis is stopped (emergency stop): clear the fault first";
  EXPECT_EQ(status_of(json{{"axis", "az"}}), 409U);
  rig.antenna.home_refusal = "this axis has no pulse sensor to home";
  EXPECT_EQ(status_of(json{{"axis", "pol"}}), 409U);
  // Any STOP ends a homing in progress, naming who stopped it.
  ASSERT_FALSE(rig.act("stop", json::object()).error.has_value());
  ASSERT_EQ(rig.antenna.homing_stopped.size(), 1U);
  EXPECT_NE(rig.antenna.homing_stopped[0].find("console"), std::string::npos);
}

TEST(DaemonConsole, AnUnknownActionIs404) {
  ConsoleRig rig;
  try {
    rig.act("launch", json::object());
    ADD_FAILURE() << "accepted";
  } catch (const ApiError& e) {
    EXPECT_EQ(e.status(), 404U);
  }
}

}  // namespace
}  // namespace azt::app
