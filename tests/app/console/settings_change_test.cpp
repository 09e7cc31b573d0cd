// PUT /api/config/SECTION[/N]'s body against the schema (settings_change.hpp): what is refused
// before anything is saved, and what the saved change writes into the file as re-read.
#include "console/settings_change.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "console/console_model.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

struct Refusal {
  unsigned status = 200;
  std::string field;
  std::string message;
};

Refusal refusal_of(std::string_view route, const json& body) {
  try {
    (void)settings_change(route, body);
  } catch (const ApiError& e) {
    return {e.status(), e.field(), e.what()};
  }
  return {};
}

/// The file after the change, saved and loaded as `serve` would.
toml::table changed(const std::string& text, std::string_view route, const json& body) {
  toml::table root = toml::parse(text);
  store_change(settings_change(route, body))(root);
  return root;
}

std::string toml_of(const toml::table& root) {
  std::ostringstream text;
  text << root;
  return text.str();
}

const std::string kFile = "[station]\ngrid = \"FN06HE\"\n[target]\nname = \"stop\"\n";

TEST(SettingsChange, AcceptsTheSchemasValues) {
  const SettingsChange c = settings_change("control", json{{"window_deg", 0.2}, {"lead", false}});
  EXPECT_EQ(c.section->name, "control");
  ASSERT_EQ(c.keys.size(), 2u);
  EXPECT_EQ(c.dotted(*c.keys[0]), "control.lead");  // a JSON object's keys come sorted
  EXPECT_EQ(c.values["window_deg"].value<double>(), 0.2);
  EXPECT_EQ(settings_change("mount.az", json{{"encoder_bits", 14}})
                .values["encoder_bits"]
                .value<std::int64_t>(),
            14);
  // A whole number for a number key is saved as one: 1.0 reads back as what was meant.
  EXPECT_TRUE(settings_change("control", json{{"ramp_s", 2}}).values["ramp_s"].is_floating_point());
  EXPECT_EQ(settings_change("park/2", json{{"name", "stow"}}).item, 2u);
  EXPECT_EQ(settings_change("sky", json{{"dx_grid", nullptr}}).removed,
            std::vector<std::string>{"dx_grid"});
}

TEST(SettingsChange, RefusesWhatTheSchemaRefusesNamingTheKey) {
  struct Case {
    const char* route;
    json body;
    unsigned status;
    const char* field;
    const char* says;
  };
  const Case cases[] = {
      {"control", {{"windw_deg", 0.1}}, 400, "windw_deg", "unknown key [control].windw_deg"},
      {"control", {{"window_deg", 3.0}}, 400, "window_deg", "[control].window_deg must be 0 to 2"},
      {"control", {{"window_deg", "0.1"}}, 400, "window_deg", "must be a number"},
      {"control", {{"window_deg", {{"x", 1}}}}, 400, "window_deg", "must be a number"},
      {"control", {{"lead", 1}}, 400, "lead", "must be true or false"},
      {"mount.el", {{"encoder_bits", 12.5}}, 400, "encoder_bits", "must be an integer"},
      {"mount.el", {{"encoder_bits", 18446744073709551615U}}, 400, "encoder_bits", "integer"},
      {"log", {{"level", "loud"}}, 400, "level", "must be \"debug\", \"info\" or \"warn\""},
      {"corrections", {{"tilt_el_deg", {1, 2}}}, 400, "tilt_el_deg", "must hold 60 numbers"},
      {"sky", {{"sources", {{"a", {1}}}}}, 400, "sources", "must be an array"},
      {"sky", {{"sources", {json::array({"x"})}}}, 400, "sources", "must hold strings"},
      {"gpio", {{"estop", -1}}, 400, "estop", "must be a line number 0 to 1023"},
      {"web", {{"password_hash", "$argon2id$"}}, 400, "password_hash", "secret"},
      {"web", {{"api_token_sha256", nullptr}}, 400, "api_token_sha256", "secret"},
      {"park/1", {{"az_deg", 360}}, 400, "az_deg", "[park#1].az_deg must be 0 to below 360"},
      {"control", json::object(), 400, "", "give the keys"},
      {"control", json::array({1}), 400, "", "give the keys"},
      {"nosuch", {{"a", 1}}, 404, "", "no settings section [nosuch]"},
      {"", {{"schema_version", 3}}, 404, "", "no settings section"},
      {"mount", {{"az", 1}}, 404, "", "no settings section [mount]"},
      {"park", {{"name", "x"}}, 400, "", "/api/config/park/N"},
      {"park/0", {{"name", "x"}}, 404, "", "no settings"},
      {"park/x", {{"name", "x"}}, 404, "", "no settings"},
      {"park/99999999999999999999", {{"name", "x"}}, 404, "", "no settings"},
      {"control/1", {{"window_deg", 0.1}}, 404, "", "no settings"},
  };
  for (const Case& c : cases) {
    const Refusal r = refusal_of(c.route, c.body);
    EXPECT_EQ(r.status, c.status) << c.route << " " << c.body.dump();
    EXPECT_EQ(r.field, c.field) << c.route << " " << c.body.dump();
    EXPECT_NE(r.message.find(c.says), std::string::npos) << c.body.dump() << ": " << r.message;
  }
}

TEST(SettingsChange, WritesOnlyTheKeysGiven) {
  const toml::table root =
      changed(kFile + "[control]\nramp_s = 2.0\n", "control", json{{"window_deg", 0.3}});
  EXPECT_EQ(root["control"]["window_deg"].value<double>(), 0.3);
  EXPECT_EQ(root["control"]["ramp_s"].value<double>(), 2.0);
  EXPECT_EQ(root["station"]["grid"].value<std::string>(), "FN06HE");
  const toml::table mount = changed(kFile, "mount.el", json{{"max_rate_deg_s", 2.0}});
  EXPECT_EQ(mount["mount"]["el"]["max_rate_deg_s"].value<double>(), 2.0);
  const toml::table removed = changed(kFile + "[sky]\ndx_grid = \"JO65\"\nband = \"432\"\n", "sky",
                                      json{{"dx_grid", nullptr}});
  EXPECT_FALSE(removed["sky"]["dx_grid"]);
  EXPECT_EQ(removed["sky"]["band"].value<std::string>(), "432");
}

TEST(SettingsChange, TheStationsGridAndPositionNeverDisagree) {
  const std::string placed = "[station]\nlat_deg = 52.0\nlon_deg = 5.0\nalt_m = 3.0\n";
  const toml::table by_grid = changed(placed, "station", json{{"grid", "JO22"}});
  EXPECT_FALSE(by_grid["station"]["lat_deg"]);
  EXPECT_FALSE(by_grid["station"]["lon_deg"]);
  EXPECT_EQ(by_grid["station"]["alt_m"].value<double>(), 3.0);
  const toml::table by_position =
      changed(kFile, "station", json{{"lat_deg", 40.0}, {"lon_deg", 1.0}});
  EXPECT_FALSE(by_position["station"]["grid"]);
  const toml::table height = changed(kFile, "station", json{{"alt_m", 20.0}});
  EXPECT_EQ(height["station"]["grid"].value<std::string>(), "FN06HE");
}

TEST(SettingsChange, ItemsAreChangedOrAddedOneAtATime) {
  const std::string two = kFile + "[[serial]]\nprotocol = \"gs232b\"\ndevice = \"pty:a\"\n";
  const toml::table baud = changed(two, "serial/1", json{{"baud", 19200}});
  EXPECT_EQ(baud["serial"][0]["baud"].value<std::int64_t>(), 19200);
  EXPECT_EQ(baud["serial"][0]["device"].value<std::string>(), "pty:a");
  const toml::table added =
      changed(two, "serial/2", json{{"protocol", "spid"}, {"device", "pty:b"}});
  EXPECT_EQ(added["serial"].as_array()->size(), 2u);
  toml::table root = toml::parse(two);
  EXPECT_THROW(store_change(settings_change("serial/3", json{{"baud", 1200}}))(root), UsageError);
}

TEST(SettingsChange, AnItemOfAnArrayOfTablesInsideATableIsWrittenThere) {
  // [[satellites.transmitter]] lives in [satellites]: never a top-level key with a dot in it.
  const std::string sats = kFile + "[satellites]\nmin_el_deg = 5.0\n";
  const toml::table added =
      changed(sats, "satellites.transmitter/1", json{{"norad", "25544"}, {"downlink_mhz", 437.8}});
  EXPECT_FALSE(added.contains("satellites.transmitter"));
  ASSERT_TRUE(added["satellites"]["transmitter"].is_array_of_tables());
  EXPECT_EQ(added["satellites"]["transmitter"][0]["norad"].value<std::string>(), "25544");
  EXPECT_EQ(added["satellites"]["min_el_deg"].value<double>(), 5.0);
  const toml::table second = changed(toml_of(added), "satellites.transmitter/2",
                                     json{{"norad", "43017"},
                                          {"downlink_mhz", 145.96},
                                          {"uplink_mhz", 435.65},
                                          {"mode", "linear_inverting"}});
  const toml::table edited =
      changed(toml_of(second), "satellites.transmitter/1", json{{"downlink_mhz", 437.805}});
  const RadioConfig radio =
      daemon_config_from(ConfigFile::parse(toml_of(edited), "saved.toml")).radio;
  ASSERT_EQ(radio.transmitters.size(), 2u);
  EXPECT_EQ(radio.transmitters[0].norad, "25544");
  EXPECT_DOUBLE_EQ(radio.transmitters[0].transmitter.downlink_hz, 437.805e6);
  EXPECT_EQ(radio.transmitters[1].transmitter.mode, radio::TransponderMode::LinearInverting);
  toml::table root = toml::parse(sats);
  EXPECT_THROW(
      store_change(settings_change("satellites.transmitter/2", json{{"norad", "1"}}))(root),
      UsageError);
}

TEST(SettingsChange, EveryLiveKeyHasAnApplyPathAndNoOtherKeyHasOne) {
  // The keys this route may change; secrets and the program's own keys (the tokens' records)
  // change through routes of their own.
  for (const SectionSpec& s : config_sections()) {
    for (const KeySpec& k : s.keys) {
      if (k.access != Access::Editable) continue;
      EXPECT_EQ(k.applies == Applies::Live, live_apply_of(s.name, k.key).has_value())
          << "[" << s.name << "]." << k.key;
    }
  }
}

TEST(SettingsChange, ASavedChangeIsAFileThatLoads) {
  // Through the loader: what the console's save validates before it writes.
  toml::table root = toml::parse(kFile);
  store_change(settings_change("hamlib", json{{"model", 603}, {"poll_s", 0.5}}))(root);
  store_change(settings_change("park/1", json{{"name", "home"}, {"az_deg", 90}}))(root);
  std::ostringstream text;
  text << root;
  const DaemonConfig c = daemon_config_from(ConfigFile::parse(text.str(), "saved.toml"));
  EXPECT_EQ(c.hamlib.model, 603);
  EXPECT_EQ(c.park[0].name, "home");
  EXPECT_DOUBLE_EQ(c.park[0].position.az_deg, 90.0);
}

}  // namespace
}  // namespace azt::app
