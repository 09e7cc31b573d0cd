// [time] (docs/time.md): the defaults a station runs with, and each bad value refused by name.
#include "config/time_config.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

TimeConfig from(const std::string& text) {
  return time_config_from(ConfigFile::parse(text, "test.toml"));
}

std::string refusal(const std::string& text) {
  try {
    from(text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(TimeConfig, DefaultsWatchChronyAndChangeNothing) {
  const TimeConfig c = from("");
  EXPECT_EQ(c.chronyc, "chronyc");
  EXPECT_EQ(c.chrony_socket, "");
  EXPECT_DOUBLE_EQ(c.poll_s, 5.0);
  EXPECT_EQ(c.rtc, "/dev/rtc0");
  EXPECT_FALSE(c.manage_chrony);
  EXPECT_EQ(c.sources_file, "/var/lib/azeltrack/chrony/azeltrack.sources");
}

TEST(TimeConfig, EveryKeyIsRead) {
  const TimeConfig c = from(
      "[time]\nchronyc = \"/usr/bin/chronyc\"\nchrony_socket = \"/run/chrony/chronyd.sock\"\n"
      "poll_s = 2\nrtc = \"/dev/rtc1\"\nmanage_chrony = true\n"
      "sources_file = \"/var/lib/azeltrack/chrony.sources\"\n");
  EXPECT_EQ(c.chronyc, "/usr/bin/chronyc");
  EXPECT_EQ(c.chrony_socket, "/run/chrony/chronyd.sock");
  EXPECT_DOUBLE_EQ(c.poll_s, 2.0);
  EXPECT_EQ(c.rtc, "/dev/rtc1");
  EXPECT_TRUE(c.manage_chrony);
  EXPECT_EQ(c.sources_file, "/var/lib/azeltrack/chrony.sources");
}

TEST(TimeConfig, BadValuesAreRefusedByName) {
  EXPECT_NE(refusal("[time]\npoll_s = 0\n").find("poll_s"), std::string::npos);
  EXPECT_NE(refusal("[time]\npoll_s = 1000\n").find("poll_s"), std::string::npos);
  EXPECT_NE(refusal("[time]\nchronyc = \"\"\n").find("chronyc"), std::string::npos);
  // chrony's sourcedir reads only *.sources files, and a relative path depends on the cwd.
  EXPECT_NE(refusal("[time]\nsources_file = \"/etc/chrony/azeltrack.conf\"\n").find("sources_file"),
            std::string::npos);
  EXPECT_NE(refusal("[time]\nsources_file = \"a.sources\"\n").find("sources_file"),
            std::string::npos);
  EXPECT_NE(refusal("[time]\nmanage_chrony = \"yes\"\n").find("manage_chrony"), std::string::npos);
  EXPECT_NE(refusal("[time]\nservers = []\n").find("servers"), std::string::npos);
}

}  // namespace
}  // namespace azt::app
