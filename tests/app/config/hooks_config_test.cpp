// [hooks] (docs/satellites.md "Hooks"): none by default; a hook is a program's path alone or a
// program with its arguments; a program not named by its absolute path, a NUL in a value, a
// value of another kind and a timeout outside its range are refused naming the key.
#include "config/hooks_config.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

HooksConfig from(const std::string& text) {
  return hooks_config_from(ConfigFile::parse(text, "test.toml"));
}

std::string refusal(const std::string& text) {
  try {
    from(text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(HooksConfig, NoneByDefault) {
  const HooksConfig c = from("");
  EXPECT_TRUE(c.aos.empty());
  EXPECT_TRUE(c.los.empty());
  EXPECT_TRUE(c.pre_position.empty());
  EXPECT_TRUE(c.park.empty());
  EXPECT_DOUBLE_EQ(c.timeout_s, 30.0);
  EXPECT_TRUE(from("[hooks]\naos = []\n").aos.empty());
}

TEST(HooksConfig, APathAloneOrAProgramWithItsArguments) {
  const HooksConfig c = from(
      "[hooks]\naos = \"/usr/local/bin/aos hook\"\n"
      "los = [\"/usr/local/bin/record\", \"--stop\", \"$AZT_SAT; rm -rf /\"]\n"
      "pre_position = [\"/bin/true\"]\npark = \"/opt/park\"\ntimeout_s = 5\n");
  EXPECT_EQ(c.aos, (std::vector<std::string>{"/usr/local/bin/aos hook"})) << "a path, not words";
  EXPECT_EQ(c.los,
            (std::vector<std::string>{"/usr/local/bin/record", "--stop", "$AZT_SAT; rm -rf /"}));
  EXPECT_EQ(c.pre_position, (std::vector<std::string>{"/bin/true"}));
  EXPECT_EQ(c.park, (std::vector<std::string>{"/opt/park"}));
  EXPECT_DOUBLE_EQ(c.timeout_s, 5.0);
}

TEST(HooksConfig, BadValuesAreRefusedNamingTheKey) {
  EXPECT_NE(refusal("[hooks]\naos = \"record.sh\"\n")
                .find("[hooks].aos must name the program by "
                      "its absolute path"),
            std::string::npos);
  EXPECT_NE(refusal("[hooks]\nlos = [\"\", \"x\"]\n").find("[hooks].los must name the program"),
            std::string::npos);
  EXPECT_NE(refusal("[hooks]\npark = [\"/bin/echo\", \"a\\u0000b\"]\n")
                .find("[hooks].park must not hold a NUL"),
            std::string::npos);
  EXPECT_NE(refusal("[hooks]\npre_position = 5\n")
                .find("[hooks].pre_position must be a string or an array"),
            std::string::npos);
  EXPECT_NE(refusal("[hooks]\naos = [\"/bin/echo\", 5]\n").find("[hooks].aos must hold strings"),
            std::string::npos);
  EXPECT_NE(refusal("[hooks]\ntimeout_s = 0\n").find("[hooks].timeout_s must be 0.1 to 3600"),
            std::string::npos);
  EXPECT_NE(refusal("[hooks]\nlos_hook = \"/bin/true\"\n").find("unknown key [hooks].los_hook"),
            std::string::npos);
}

}  // namespace
}  // namespace azt::app
