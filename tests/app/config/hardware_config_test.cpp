// The [hardware.az] and [hardware.el] settings (docs/hardware.md): each mistake is refused naming
// its key, numbers are checked before they are narrowed.
#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

TEST(HardwareConfig, MistakesNameTheKey) {
  const auto error_of = [](const std::string& extra) {
    try {
      (void)daemon_config_from(ConfigFile::parse(
          "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"hardware\"\n[hub]\ndevice = "
          "\"/dev/null\"\n" +
              extra,
          "c.toml"));
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error_of(""), "");
  EXPECT_NE(
      error_of("[hardware.az]\ndrive = \"relay\"\nrelay_forward = 5\n").find("[hardware.az].drive"),
      std::string::npos);
  EXPECT_NE(error_of("[hardware.el]\ndrive = \"pot\"\nspi_device = \"/dev/spidev0.0\"\n")
                .find("[hardware.el].wiper_calibration"),
            std::string::npos);
  EXPECT_NE(error_of("[hardware.az]\nsensor = \"mcp3008\"\nadc_device = \"/dev/spidev0.1\"\n")
                .find("[hardware.az].pot_calibration"),
            std::string::npos);
  EXPECT_NE(error_of("[hardware.az]\nsensor = \"ads1115\"\nadc_device = \"/dev/i2c-1\"\n"
                     "adc_channel = 4\npot_calibration = [0, 0, 100, 90]\n")
                .find("[hardware.az].adc_channel"),
            std::string::npos);
  EXPECT_NE(error_of("[hardware.az]\ndrive = \"stepper\"\n").find("[hardware.az].drive must be"),
            std::string::npos);
  EXPECT_NE(error_of("[gpio]\nestop = 5\n[hardware.az]\ndrive = \"relay\"\nrelay_forward = 5\n"
                     "relay_reverse = 6\n")
                .find("same line as [gpio] estop"),
            std::string::npos);
  // Numbers are checked before they are narrowed: 4294967297 is not 1 (docs/reliability.md
  // "Hardening" row 9).
  const std::string pot =
      "[hardware.az]\nsensor = \"mcp3008\"\nadc_device = \"/dev/spidev0.1\"\n"
      "pot_calibration = [0, 0, 1000, 450]\n";
  EXPECT_EQ(error_of(pot + "open_below_counts = 1\n"), "");
  EXPECT_NE(
      error_of(pot + "open_below_counts = 4294967297\n").find("[hardware.az].open_below_counts"),
      std::string::npos);
  EXPECT_NE(
      error_of(pot + "open_above_counts = -4294967295\n").find("[hardware.az].open_above_counts"),
      std::string::npos);
  EXPECT_NE(error_of(pot + "average_samples = -1\n").find("[hardware.az].average_samples"),
            std::string::npos);
}

}  // namespace
}  // namespace azt::app
