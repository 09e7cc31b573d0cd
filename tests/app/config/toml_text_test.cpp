// Saved settings read back exactly what was saved (a surveyed station position had once been cut
// to 6 significant digits, metres away), and still read as people write them.
#include "config/toml_text.hpp"

#include <gtest/gtest.h>

namespace azt::app {
namespace {

TEST(TomlText, FloatsReadBackToTheSameDouble) {
  toml::table t;
  t.insert("lat_deg", 46.18957795825);
  t.insert("lon_deg", -79.39374529175001);
  t.insert("tiny", 1.25e-9);
  const std::string text = toml_text(t);
  const toml::table back = toml::parse(text);
  EXPECT_EQ(back["lat_deg"].value<double>(), 46.18957795825) << text;
  EXPECT_EQ(back["lon_deg"].value<double>(), -79.39374529175001) << text;
  EXPECT_EQ(back["tiny"].value<double>(), 1.25e-9) << text;
}

TEST(TomlText, FloatsAreWrittenAsPeopleWriteThem) {
  toml::table t;
  t.insert("a", 0.1);
  t.insert("b", 300.0);
  t.insert("c", -2.5);
  t.insert("n", 42);
  const std::string text = toml_text(t) + "\n";
  EXPECT_NE(text.find("a = 0.1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("b = 300.0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("c = -2.5\n"), std::string::npos) << text;
  EXPECT_NE(text.find("n = 42\n"), std::string::npos) << text;
}

TEST(TomlText, StringsCommentsAndDatesAreLeftAlone) {
  const std::string in =
      "s = \"0.10000000000000001 \\\" 2.50\"\nl = '3.000'\n# 1.50\nd = 2025-03-14T00:00:00Z\n"
      "f = 0.10000000000000001\nv = [1.50, 2.0]\n";
  const std::string out = shortest_floats(in);
  EXPECT_EQ(out,
            "s = \"0.10000000000000001 \\\" 2.50\"\nl = '3.000'\n# 1.50\nd = 2025-03-14T00:00:00Z\n"
            "f = 0.1\nv = [1.5, 2.0]\n");
}

}  // namespace
}  // namespace azt::app
