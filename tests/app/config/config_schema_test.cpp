// The configuration schema (config_schema.hpp) against the loader that checks files with it: every
// key the examples use is described, every default and choice it lists loads, every value outside
// a described range or of the wrong type is refused naming the key and its line.
#include "config/config_schema.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "config/toml_text.hpp"

namespace azt::app {
namespace {

// Schema 2: an older file would be migrated first ([sim.az] keys moving to [mount.az]).
const std::string kVersion = "schema_version = 2\n";
const std::string kStation = "[station]\ngrid = \"FN06HE\"\n";
const std::string kTarget = "[target]\nname = \"stop\"\n";
const std::string kDataDir = AZT_TEST_DATA_DIR;

/// "" when `text`, with a station and a target unless it has its own, loads as `serve` would;
/// else the error.
std::string load_error(const std::string& text) {
  const bool own_station = text.rfind("[station]\n", 0) == 0;
  const bool own_target = text.rfind("[target]\n", 0) == 0;
  const std::string file =
      kVersion + (own_station ? "" : kStation) + (own_target ? "" : kTarget) + text;
  try {
    (void)daemon_config_from(ConfigFile::parse(file, "schema.toml"));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

/// What a section needs beside `key` to load: the station's place, an item's required keys.
std::string context_of(const SectionSpec& s, std::string_view key) {
  std::map<std::string_view, std::string> needed;
  if (s.name == "station") {
    if (key == "lat_deg") return "lon_deg = 5.0\n";
    if (key == "lon_deg") return "lat_deg = 50.0\n";
    needed = {{"grid", "\"FN06HE\""}};
  }
  if (s.name == "serial") needed = {{"protocol", "\"gs232b\""}, {"device", "\"pty:azt-test\""}};
  if (s.name == "schedule") needed = {{"sat", "\"ISS\""}};
  if (s.name == "satellites.transmitter") {
    needed = {{"norad", "\"25544\""}, {"downlink_mhz", "437.8"}, {"uplink_mhz", "145.99"}};
  }
  if (s.name == "radio") needed = {{"rigctld", "\"127.0.0.1:4532\""}, {"dial_mhz", "1296.1"}};
  if (s.name == "spacecraft") {
    needed = {{"name", "\"Probe\""},
              {"file", "\"" + kDataDir + "/horizons/moon_vectors_csv_kms.txt\""}};
  }
  // The pol axis's sensor is a pot that must be given (the EncoderHub reads az and el only).
  if (s.name == "hardware.pol" && key != "sensor") {
    needed = {{"sensor", "\"mcp3008\""},
              {"adc_device", "\"/dev/spidev0.0\""},
              {"pot_calibration", "[100.0, -90.0, 900.0, 90.0]"}};
  }
  // A simulated brake's and winding's keys are refused without the brake or the winding.
  if (s.name == "sim.az" || s.name == "sim.el") {
    if (key.starts_with("brake_")) needed = {{"brake", "true"}};
    if ((key.starts_with("motor_") && key != "motor_heating") || key == "ambient_c" ||
        key.starts_with("temperature_")) {
      needed = {{"motor_heating", "true"}, {"temperature_limit_c", "80.0"}};
    }
  }
  std::string out;
  for (const auto& [k, v] : needed) {
    if (k != key) out += std::string(k) + " = " + v + "\n";
  }
  return out;
}

/// `[section]` (or `[[section]]`) holding `key = value_toml`, with its context.
std::string table_with(const SectionSpec& s, std::string_view key, const std::string& value_toml) {
  const std::string head =
      s.array_of_tables ? "[[" + std::string(s.name) + "]]\n" : "[" + std::string(s.name) + "]\n";
  // [hardware.pol] drives the axis [mount.pol] describes: without it the file is refused.
  const std::string before = s.name == "hardware.pol" ? "[mount.pol]\n" : "";
  return before + head + context_of(s, key) + std::string(key) + " = " + value_toml + "\n";
}

/// The choices that need another table to be usable: the backend's device, the receiver's input,
/// an ADC's or a pot's settings.
std::string choice_context(const SectionSpec& s, std::string_view choice) {
  if (s.name == "antenna" && choice == "hamlib") return "[hamlib]\nmodel = 1\n";
  if (s.name == "antenna" && (choice == "pwm" || choice == "hardware")) {
    return "[hub]\ndevice = \"/dev/ttyUSB9\"\n";
  }
  return "";
}

std::string choice_extra_keys(const SectionSpec& s, std::string_view key, std::string_view choice) {
  if (s.name == "receiver" && choice == "rtl_power") return "path = \"/tmp/power.csv\"\n";
  if (s.name == "receiver" && choice == "udp") return "port = 12070\n";
  if (key == "sensor" && (choice == "mcp3008" || choice == "ads1115")) {
    return "adc_device = \"/dev/spidev0.0\"\npot_calibration = [100.0, 0.0, 900.0, 360.0]\n";
  }
  if (choice == "relay") return "relay_forward = 5\nrelay_reverse = 6\n";
  if (choice == "pulses") return "pulse_line = 12\nhome_switch = 13\ncounts_per_deg = 2.0\n";
  if (choice == "stepdir") return "step_channel = 2\ndir = 17\n";
  if (choice == "pot") {
    return "spi_device = \"/dev/spidev0.1\"\nwiper_calibration = [10.0, 0.0, 250.0, 360.0]\n";
  }
  return "";
}

std::string toml_number(KeyType type, double v) {
  if (type == KeyType::Integer) return std::to_string(static_cast<std::int64_t>(v));
  return toml_text(toml::value<double>(v));
}

/// A value of the wrong kind for `type`.
std::string wrong_kind(KeyType type) {
  switch (type) {
    case KeyType::Boolean:
      return "\"yes\"";
    case KeyType::Integer:
      return "1.5";
    case KeyType::Number:
      return "\"1\"";
    case KeyType::Text:
    case KeyType::Choice:
      return "5";
    case KeyType::GpioLine:
      return "1.5";
    case KeyType::TextList:
    case KeyType::NumberList:
    case KeyType::IntegerList:
      return "5";
  }
  return "{}";
}

/// "[control].window_deg", "[park#1].az_deg": how the loader names the key.
std::string named(const SectionSpec& s, std::string_view key) {
  return "[" + std::string(s.name) + (s.array_of_tables ? "#1" : "") + "]." + std::string(key);
}

/// Every key of every example file is in the schema, and the file loads.
void expect_described(const toml::table& t, const SectionSpec& spec, const std::string& where) {
  for (const auto& [key, value] : t) {
    const std::string k(key.str());
    if (const SectionSpec* child = find_child(spec, k)) {
      if (const toml::table* sub = value.as_table()) expect_described(*sub, *child, where);
      if (const toml::array* items = value.as_array()) {
        for (const auto& item : *items) expect_described(*item.as_table(), *child, where);
      }
      continue;
    }
    EXPECT_NE(find_key(spec, k), nullptr) << where << ": [" << spec.name << "]." << k;
  }
}

TEST(ConfigSchema, DescribesEveryKeyOfTheExamples) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(AZT_SOURCE_DIR "/examples")) {
    if (entry.path().extension() != ".toml") continue;
    ++files;
    const ConfigFile file = ConfigFile::load(entry.path().string());
    EXPECT_NO_THROW((void)daemon_config_from(file)) << entry.path();
    expect_described(file.root(), *find_section(""), entry.path().string());
  }
  EXPECT_GE(files, 3u);
}

TEST(ConfigSchema, SectionsAndKeysAreUniqueAndDescribed) {
  std::map<std::string, int> seen;
  std::size_t keys = 0;
  for (const SectionSpec& s : config_sections()) {
    EXPECT_EQ(++seen[std::string(s.name)], 1) << "section [" << s.name << "] twice";
    EXPECT_FALSE(s.title.empty()) << s.name;
    std::map<std::string_view, int> names;
    for (const KeySpec& k : s.keys) {
      ++keys;
      EXPECT_EQ(++names[k.key], 1) << "[" << s.name << "]." << k.key << " twice";
      EXPECT_FALSE(k.help.empty()) << "[" << s.name << "]." << k.key;
      const bool choices = k.type == KeyType::Choice;
      EXPECT_EQ(choices, !k.choices.empty() && k.type != KeyType::Integer)
          << "[" << s.name << "]." << k.key;
    }
  }
  EXPECT_GT(keys, 200u) << "the schema describes every key of the file";
}

TEST(ConfigSchema, EveryDefaultLoads) {
  for (const SectionSpec& s : config_sections()) {
    for (const KeySpec& k : s.keys) {
      if (k.default_toml.empty() || s.name.empty()) continue;
      EXPECT_EQ(load_error(table_with(s, k.key, std::string(k.default_toml))), "")
          << "[" << s.name << "]." << k.key << " = " << k.default_toml;
      // The default is what the key means when absent: it passes its own check.
      const toml::table parsed = toml::parse("v = " + std::string(k.default_toml));
      EXPECT_EQ(key_violation(k, *parsed.get("v")), std::nullopt) << s.name << "." << k.key;
    }
  }
}

TEST(ConfigSchema, EveryChoiceLoads) {
  for (const SectionSpec& s : config_sections()) {
    for (const KeySpec& k : s.keys) {
      for (const std::string_view c : k.choices) {
        const std::string value =
            k.type == KeyType::Integer ? std::string(c) : "\"" + std::string(c) + "\"";
        const std::string text =
            choice_context(s, c) + table_with(s, k.key, value) + choice_extra_keys(s, k.key, c);
        EXPECT_EQ(load_error(text), "") << text;
      }
      if (k.choices.empty()) continue;
      const std::string bad = k.type == KeyType::Integer ? "7" : "\"no-such-choice\"";
      const std::string error = load_error(table_with(s, k.key, bad));
      EXPECT_NE(error.find(named(s, k.key) + " must be "), std::string::npos) << error;
    }
  }
}

TEST(ConfigSchema, ValuesOutsideEveryRangeAreRefusedNamingTheKey) {
  std::size_t bounds = 0;
  for (const SectionSpec& s : config_sections()) {
    for (const KeySpec& k : s.keys) {
      if (k.type != KeyType::Number && k.type != KeyType::Integer) continue;
      for (const double outside : {k.range.max + 1.0, k.range.min - 1.0}) {
        if (!std::isfinite(outside)) continue;
        ++bounds;
        const std::string error = load_error(table_with(s, k.key, toml_number(k.type, outside)));
        EXPECT_NE(error.find(named(s, k.key) + " must be " + range_text(k.range)),
                  std::string::npos)
            << named(s, k.key) << " = " << outside << ": " << error;
        EXPECT_NE(error.find("line "), std::string::npos) << error;
      }
    }
  }
  EXPECT_GT(bounds, 100u);
}

TEST(ConfigSchema, ValuesOfTheWrongKindAreRefusedNamingTheKey) {
  for (const SectionSpec& s : config_sections()) {
    if (s.name.empty()) continue;  // schema_version: the migrations' own check
    for (const KeySpec& k : s.keys) {
      const std::string error = load_error(table_with(s, k.key, wrong_kind(k.type)));
      EXPECT_NE(error.find(named(s, k.key) + " must "), std::string::npos)
          << named(s, k.key) << ": " << error;
    }
  }
}

TEST(ConfigSchema, RefusalsSayTheRuleAndTheLine) {
  EXPECT_NE(load_error("[control]\nwindow_deg = 3.0\n")
                .find("line 7: [control].window_deg must be 0 to 2"),
            std::string::npos);
  EXPECT_NE(load_error("[control]\ntracking_speed = 0.0\n")
                .find("[control].tracking_speed must be above 0 and at most 1"),
            std::string::npos);
  EXPECT_NE(load_error("[control]\npark_az_deg = 360.0\n")
                .find("[control].park_az_deg must be 0 to below 360"),
            std::string::npos);
  EXPECT_NE(load_error("[pointing]\nia_deg = -10.5\n").find("[pointing].ia_deg must be within ±10"),
            std::string::npos);
  EXPECT_NE(load_error("[log]\nlevel = \"loud\"\n")
                .find("[log].level must be \"debug\", \"info\" or \"warn\""),
            std::string::npos);
  EXPECT_NE(load_error("[corrections]\ntilt_el_deg = [1.0]\n")
                .find("[corrections].tilt_el_deg must hold 60 numbers"),
            std::string::npos);
  EXPECT_NE(load_error("[gpio]\nsequencer = [1, 2000]\n")
                .find("[gpio].sequencer must hold integers 0 to 1023"),
            std::string::npos);
  EXPECT_NE(load_error("[gpio]\nestop = \"gpiochip1:2000\"\n").find("[gpio].estop must be a line"),
            std::string::npos);
  EXPECT_NE(load_error("[sim.receiver]\nflux_mhz = 1297\n")
                .find("[sim.receiver].flux_mhz must be 1296, 2304 or 10368"),
            std::string::npos);
  EXPECT_NE(load_error("[control]\nspeed = 1\n").find("line 7: unknown key [control].speed"),
            std::string::npos);
  EXPECT_NE(load_error("[contrl]\nwindow_deg = 1\n").find("line 6: unknown table or key 'contrl'"),
            std::string::npos);
  EXPECT_NE(load_error("[mount]\naz = 1\n").find("[mount.az] must be a table"), std::string::npos);
  // The rules between keys stay with the readers.
  EXPECT_NE(load_error("[rotctld]\nidle_timeout_s = 5.0\n").find("[rotctld].idle_timeout_s"),
            std::string::npos);
  EXPECT_NE(load_error("[station]\nlat_deg = 50.0\n").find("go together"), std::string::npos);
}

TEST(ConfigSchema, RangesReadAsTheyAreMeant) {
  EXPECT_EQ(range_text(closed(0.0, 2.0)), "0 to 2");
  EXPECT_EQ(range_text(within(10.0)), "within ±10");
  EXPECT_EQ(range_text(above_up_to(0.0, 1.0)), "above 0 and at most 1");
  EXPECT_EQ(range_text(from_below(0.0, 360.0)), "0 to below 360");
  EXPECT_EQ(range_text(above(0.0)), "above 0");
  EXPECT_EQ(range_text(at_least(0.5)), "at least 0.5");
  EXPECT_EQ(range_text(closed(1.0, 1e6)), "1 to 1000000");
  EXPECT_EQ(range_text(Range{}), "");
}

TEST(ConfigSchema, LiveKeysAreTheConsolesAndSecretsAreTheWebs) {
  std::vector<std::string> live;
  std::vector<std::string> secret;
  for (const SectionSpec& s : config_sections()) {
    for (const KeySpec& k : s.keys) {
      const std::string name = std::string(s.name) + "." + std::string(k.key);
      if (k.applies == Applies::Live) live.push_back(name);
      if (k.access == Access::Secret) secret.push_back(name);
    }
  }
  EXPECT_EQ(secret, (std::vector<std::string>{"web.password_hash", "web.api_token_sha256",
                                              "token.sha256"}));
  for (const char* name : {"station.grid", "sky.band", "sky.dx_grid", "corrections.tilt_el_deg",
                           "park.az_deg", "pointing.ia_deg"}) {
    EXPECT_NE(std::find(live.begin(), live.end(), name), live.end()) << name;
  }
  EXPECT_EQ(std::find(live.begin(), live.end(), "control.window_deg"), live.end());
}

}  // namespace
}  // namespace azt::app
