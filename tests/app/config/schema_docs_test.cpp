// docs/configuration.md's key reference is the program's (`azeltrack config schema --markdown`):
// a key added, changed or described differently in the schema fails here until
// scripts/gen-config-docs has written it into the page. The JSON form lists the same keys.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "config/config_schema.hpp"
#include "config/schema_json.hpp"
#include "config/schema_markdown.hpp"

namespace azt::app {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The page's text between its markers, without the newlines next to them.
std::string generated_part(const std::string& page) {
  const auto begin = page.find(kGeneratedBegin);
  const auto end = page.find(kGeneratedEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin) return "<no markers>";
  const std::size_t from = begin + kGeneratedBegin.size() + 1;
  return page.substr(from, end - from - 1);
}

TEST(SchemaDocs, ConfigurationPageHoldsTheGeneratedReference) {
  const std::string page = read(AZT_SOURCE_DIR "/docs/configuration.md");
  ASSERT_FALSE(page.empty());
  EXPECT_TRUE(generated_part(page) == schema_markdown())
      << "docs/configuration.md's reference differs from the schema: run scripts/gen-config-docs";
  // The hand-written rules stay around it.
  EXPECT_NE(page.find("## Which file, and the rules"), std::string::npos);
  EXPECT_NE(page.find("## How it is saved"), std::string::npos);
}

TEST(SchemaDocs, TheReferenceShowsEveryKeyOnce) {
  const std::string text = schema_markdown();
  for (const SectionSpec& s : config_sections()) {
    for (const KeySpec& k : s.keys) {
      EXPECT_NE(text.find("| `" + std::string(k.key) + "` |"), std::string::npos) << k.key;
    }
    if (s.keys.empty()) continue;
    const std::string name(s.name);
    const std::string heading = s.array_of_tables ? "`[[" + name + "]]`" : "`[" + name + "]`";
    EXPECT_NE(text.find(s.name.empty() ? "The file's top level" : heading), std::string::npos)
        << heading;
  }
}

TEST(SchemaDocs, TheJsonListsEverySectionWithKeys) {
  const auto& schema = schema_json();
  std::size_t sections = 0;
  for (const SectionSpec& s : config_sections()) {
    if (s.name.empty() || s.keys.empty()) continue;
    ++sections;
    const auto it = std::find_if(schema["sections"].begin(), schema["sections"].end(),
                                 [&s](const auto& j) { return j["name"] == s.name; });
    ASSERT_NE(it, schema["sections"].end()) << s.name;
    EXPECT_EQ((*it)["keys"].size(), s.keys.size()) << s.name;
  }
  EXPECT_EQ(schema["sections"].size(), sections);
  EXPECT_EQ(schema["schema_version"], 2);
}

TEST(SchemaDocs, TheJsonGivesValuesButNeverSecrets) {
  const toml::table root = toml::parse(
      "[control]\nwindow_deg = 0.25\n[web]\npassword_hash = \"$argon2id$x\"\nport = 8090\n"
      "[[park]]\nname = \"home\"\n");
  const auto schema = schema_json_with_values(root);
  const auto key_of = [&schema](const std::string& section, const std::string& key) {
    for (const auto& s : schema["sections"]) {
      for (const auto& k : s["keys"]) {
        if (s["name"] == section && k["key"] == key) return k;
      }
    }
    return nlohmann::json();
  };
  EXPECT_EQ(key_of("control", "window_deg")["value"], 0.25);
  EXPECT_EQ(key_of("control", "window_deg")["default"], 0.0);
  EXPECT_EQ(key_of("control", "window_deg")["range"]["max"], 2.0);
  EXPECT_EQ(key_of("control", "window_deg")["applies"], "restart");
  EXPECT_TRUE(key_of("control", "ramp_s")["value"].is_null()) << "absent: the default applies";
  EXPECT_EQ(key_of("web", "port")["value"], 8090);
  EXPECT_EQ(key_of("web", "password_hash")["access"], "secret");
  EXPECT_TRUE(key_of("web", "password_hash")["value"].is_null());
  for (const auto& s : schema["sections"]) {
    if (s["name"] != "park") continue;
    ASSERT_EQ(s["items"].size(), 1u);
    EXPECT_EQ(s["items"][0]["name"], "home");
  }
  EXPECT_EQ(schema.dump().find("argon2id"), std::string::npos);
}

TEST(SchemaDocs, TheItemsOfAnArrayOfTablesInsideATableAreGiven) {
  // [[satellites.transmitter]] is an array inside [satellites], not a top-level key named
  // "satellites.transmitter": its items were once listed as none.
  const toml::table root = toml::parse(
      "[satellites]\n[[satellites.transmitter]]\nnorad = \"25544\"\ndownlink_mhz = 437.8\n"
      "[[satellites.transmitter]]\nnorad = \"43017\"\ndownlink_mhz = 145.96\n"
      "uplink_mhz = 435.65\nmode = \"linear_inverting\"\n");
  const auto schema = schema_json_with_values(root);
  const auto it = std::find_if(schema["sections"].begin(), schema["sections"].end(),
                               [](const auto& j) { return j["name"] == "satellites.transmitter"; });
  ASSERT_NE(it, schema["sections"].end());
  ASSERT_EQ((*it)["items"].size(), 2u) << (*it)["items"].dump();
  EXPECT_EQ((*it)["items"][0]["norad"], "25544");
  EXPECT_EQ((*it)["items"][1]["mode"], "linear_inverting");
  EXPECT_EQ((*it)["items"][1]["uplink_mhz"], 435.65);
}

}  // namespace
}  // namespace azt::app
