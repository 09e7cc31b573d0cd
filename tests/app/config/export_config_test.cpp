// [export] (docs/eme.md): azel.dat off by default, an absolute file path when set.
#include "config/export_config.hpp"

#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

ExportConfig from(const std::string& text) {
  return export_config_from(ConfigFile::parse(text, "test.toml"));
}

TEST(ExportConfig, AzelDatIsOffUnlessSet) {
  EXPECT_EQ(from("").azel_dat, "");
  EXPECT_EQ(from("[export]\nazel_dat = \"/home/op/.local/share/WSJT-X/azel.dat\"\n").azel_dat,
            "/home/op/.local/share/WSJT-X/azel.dat");
  EXPECT_FALSE(from("").azel_dat_pol_line);  // four lines, as WSJT-X by default
  EXPECT_TRUE(from("[export]\nazel_dat_pol_line = true\n").azel_dat_pol_line);
  EXPECT_THROW(from("[export]\nazel_dat_pol_line = 1\n"), UsageError) << "not a boolean";
}

TEST(ExportConfig, ARelativePathOrAFolderIsRefused) {
  for (const char* bad : {"azel.dat", "/tmp/", "~/azel.dat"}) {
    try {
      from(std::string("[export]\nazel_dat = \"") + bad + "\"\n");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("azel_dat"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(from("[export]\nazel = \"/x\"\n"), UsageError) << "an unknown key";
}

}  // namespace
}  // namespace azt::app
