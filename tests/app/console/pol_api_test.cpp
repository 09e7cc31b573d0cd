// The polarisation axis in the console (console/pol_actions.cpp, docs/web-api.md): /api/state's
// `pol` object, and POST /api/pol choosing the mode and the angle, saved as [pol] and followed;
// hostile bodies refused naming the field with nothing saved or moved; refused as a move is
// while a fault is latched (off excepted). The antenna is the simulated one with a pol plant,
// ticked in virtual time; Dpol is a constant; saves run inline.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "azt/astro/erfa_ephemeris.hpp"
#include "console/daemon_console.hpp"

namespace azt::app {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr const char* kPolStation = R"(schema_version = 2
[station]
grid = "FN20"
[target]
name = "stop"
[mount.pol]
max_rate_deg_s = 5.0
[pol]
mode = "off"
)";

std::string read(const fs::path& p) {
  std::ostringstream s;
  s << std::ifstream(p).rdbuf();
  return s.str();
}

fs::path station_file(const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("azt-pol-api-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "azeltrack.toml") << text;
  return dir / "azeltrack.toml";
}

struct PolRig {
  explicit PolRig(const std::string& text = kPolStation) : file(station_file(text)) {}
  ~PolRig() { fs::remove_all(file.parent_path()); }

  fs::path file;
  ConfigStore store = ConfigStore::open(file.string());
  DaemonConfig config = store.config();
  astro::ErfaEphemeris ephemeris;
  SkyFollower sky{ephemeris, config.sky};
  control::ModeController modes{config.park, config.out_of_range, config.station.el_range.min_deg};
  std::unique_ptr<AntennaBackend> antenna = make_sim_backend(config);
  double now_s = 0.0;
  bool keyed = false;
  std::unique_ptr<PolFollower> pol =
      antenna->pol_status() ? std::make_unique<PolFollower>(PolFollowerParts{
                                  config.pol, [](double) { return std::optional<double>(12.0); },
                                  [this] { return keyed; }})
                            : nullptr;
  StationCommands commands{StationCommandParts{modes, *antenna, sky, nullptr,
                                               config.target_limits(), config.station.el_range,
                                               [this] { return now_s; }, [] { return 1.8e9; }, 0.0,
                                               [](const CommandSource&, const CommandRecord&) {},
                                               [](const CommandSource&, const Refusal&) {}}};
  DaemonConsole console{ConsoleParts{config,
                                     store,
                                     ephemeris,
                                     sky,
                                     modes,
                                     commands,
                                     *antenna,
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
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     nullptr,
                                     {},
                                     {},
                                     nullptr,
                                     nullptr,
                                     pol.get()}};

  ActResult act(const json& body) {
    std::optional<ActResult> got;
    console.act("pol", body, "console 127.0.0.1", [&](ActResult r) { got = std::move(r); });
    if (!got) ADD_FAILURE() << "not answered";
    return got.value_or(ActResult{});
  }
  /// The daemon's tick for `seconds`: the follower's demand, then the antenna's tick.
  void run(double seconds) {
    for (const double end = now_s + seconds; now_s < end; now_s += 0.05) {
      antenna->set_pol_demand(pol->demand(1.8e9 + now_s));
      antenna->tick(now_s, modes.demand(std::nullopt), {});
    }
  }
  /// The refusal of `body`: its status and field, "" when it was accepted.
  std::string refusal(const json& body) {
    try {
      const ActResult r = act(body);
      if (r.error) return std::to_string(r.error->status()) + " " + r.error->field();
    } catch (const ApiError& e) {
      return std::to_string(e.status()) + " " + e.field();
    }
    return "";
  }
};

TEST(PolApi, TheStateShowsThePolAxis) {
  PolRig rig;
  rig.run(0.5);
  const json p = rig.console.state()["pol"];
  ASSERT_TRUE(p.is_object()) << p.dump();
  EXPECT_EQ(p["mode"], "off");
  EXPECT_TRUE(p["feed_target_deg"].is_null()) << "off: no target";
  EXPECT_TRUE(p["mount_deg"].is_number());
  EXPECT_NEAR(p["dpol_deg"].get<double>(), 12.0, 1e-9);
  EXPECT_EQ(p["transmitting"], false);
  EXPECT_EQ(p["moving"], false);
  EXPECT_EQ(p["faults"], json::array());
  EXPECT_DOUBLE_EQ(p["max_deg"].get<double>(), 95.0);
}

TEST(PolApi, AManualAngleTurnsTheFeedAndTheModeIsSaved) {
  PolRig rig;
  const ActResult r = rig.act(json{{"mode", "manual"}, {"angle_deg", 30.0}});
  ASSERT_FALSE(r.error.has_value()) << r.error->what();
  EXPECT_EQ(r.fields["pol"]["mode"], "manual");
  EXPECT_NE(read(rig.file).find("mode = \"manual\""), std::string::npos) << read(rig.file);
  rig.run(15.0);
  const json p = rig.console.state()["pol"];
  EXPECT_NEAR(p["feed_target_deg"].get<double>(), 30.0, 1e-9);
  EXPECT_NEAR(p["mount_deg"].get<double>(), 30.0, 1.0);
  EXPECT_EQ(p["manual_deg"], 30.0);

  ASSERT_FALSE(rig.act(json{{"mode", "fixed"}, {"angle_deg", -45.0}}).error.has_value());
  EXPECT_NE(read(rig.file).find("fixed_deg = -45"), std::string::npos) << read(rig.file);
  EXPECT_EQ(rig.config.pol.mode, control::PolMode::Fixed);
  ASSERT_FALSE(rig.act(json{{"mode", "split"}}).error.has_value());
  rig.keyed = true;
  rig.run(0.1);
  EXPECT_EQ(rig.console.state()["pol"]["transmitting"], true);
}

TEST(PolApi, HostileBodiesAreRefusedNamingTheFieldAndNothingIsSaved) {
  PolRig rig;
  const std::string before = read(rig.file);
  EXPECT_EQ(rig.refusal(json{{"mode", "sideways"}}), "400 mode");
  EXPECT_EQ(rig.refusal(json{{"angle_deg", 10.0}}), "400 mode");
  EXPECT_EQ(rig.refusal(json{{"mode", 3}}), "400 mode");
  EXPECT_EQ(rig.refusal(json::array({"manual", 30})), "400 mode");
  EXPECT_EQ(rig.refusal(json{{"mode", "manual"}, {"angle_deg", 1e300}}), "400 angle_deg");
  EXPECT_EQ(rig.refusal(json{{"mode", "manual"}, {"angle_deg", "30"}}), "400 angle_deg");
  EXPECT_EQ(rig.refusal(json{{"mode", "manual"}, {"angle_deg", nullptr}}), "400 angle_deg");
  EXPECT_EQ(rig.refusal(json{{"mode", "dx"}, {"angle_deg", 5.0}}), "400 angle_deg");
  EXPECT_EQ(read(rig.file), before);
  rig.run(1.0);
  EXPECT_TRUE(rig.console.state()["pol"]["feed_target_deg"].is_null()) << "moved";
}

TEST(PolApi, ALatchedFaultRefusesAMoveButNotOff) {
  PolRig rig;
  rig.antenna->stop_now(rig.now_s);  // latched: "stopped by the daemon"
  EXPECT_EQ(rig.refusal(json{{"mode", "manual"}, {"angle_deg", 20.0}}), "409 ");
  EXPECT_EQ(rig.refusal(json{{"mode", "off"}}), "");
}

TEST(PolApi, AStationWithoutAPolAxisHasNone) {
  PolRig rig("schema_version = 2\n[station]\ngrid = \"FN20\"\n[target]\nname = \"stop\"\n");
  EXPECT_TRUE(rig.console.state()["pol"].is_null());
  EXPECT_EQ(rig.refusal(json{{"mode", "manual"}}), "404 ");
}

}  // namespace
}  // namespace azt::app
