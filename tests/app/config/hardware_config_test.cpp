// The [hardware.az] and [hardware.el] settings (docs/hardware.md): each mistake is refused naming
// its key, numbers are checked before they are narrowed.
#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "support/hardware_station.hpp"

namespace azt::app {
namespace {

/// A station on the `hardware` backend, its tables to follow.
const std::string kTop =
    "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"hardware\"\n[hub]\ndevice = "
    "\"/dev/null\"\n";

/// The configuration error of the test station with `extra` added; empty when it loads.
std::string error_or_empty(const std::string& extra) {
  try {
    (void)daemon_config_from(ConfigFile::parse(kTop + extra, "c.toml"));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(HardwareConfig, MistakesNameTheKey) {
  const auto error_of = error_or_empty;
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
  // A stepper needs its STEP channel and DIR line, and a pull-in rate it can reach.
  const std::string stepper = "[hardware.az]\ndrive = \"stepdir\"\n";
  EXPECT_EQ(error_of(stepper + "step_channel = 2\ndir = 17\nenable = 27\n"), "");
  EXPECT_NE(error_of(stepper + "dir = 17\n").find("[hardware.az].step_channel"), std::string::npos);
  EXPECT_NE(error_of(stepper + "step_channel = 2\n").find("[hardware.az].dir"), std::string::npos);
  EXPECT_NE(error_of(stepper + "step_channel = 2\ndir = 17\nmax_step_hz = 500\n"
                               "start_step_hz = 800\n")
                .find("[hardware.az].start_step_hz"),
            std::string::npos);
  EXPECT_NE(error_of(stepper + "step_channel = 99\ndir = 17\n").find("[hardware.az].step_channel"),
            std::string::npos);
  EXPECT_NE(error_of("[hardware.az]\ndrive = \"relay\"\nrelay_forward = 5\nrelay_reverse = 6\n"
                     "enable = 27\n")
                .find("\"stepdir\" (the driver's)"),
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

// A fixed elevation ([mount.el] fixed_deg) has no elevation hardware: the table is refused, the
// hub reads azimuth only, and the value's range is the schema's.
TEST(HardwareConfig, AFixedElevationHasNoElevationHardware) {
  const std::string base =
      "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"hardware\"\n[hub]\ndevice = "
      "\"/dev/null\"\n[mount.el]\nfixed_deg = 12.0\n";
  const DaemonConfig c = daemon_config_from(ConfigFile::parse(base, "c.toml"));
  ASSERT_TRUE(c.mount.el_fixed.has_value());
  EXPECT_DOUBLE_EQ(c.mount.el_fixed->el_deg, 12.0);
  EXPECT_DOUBLE_EQ(c.mount.el_fixed->beam_width_deg, 20.0);
  EXPECT_EQ(c.station.el_fixed_deg, 12.0);
  EXPECT_FALSE(c.hardware.el_axis);
  EXPECT_EQ(c.hardware.axes().size(), 1U);
  EXPECT_TRUE(c.mount.el_fixed->in_beam(21.9));
  EXPECT_FALSE(c.mount.el_fixed->in_beam(22.1));
  try {
    (void)daemon_config_from(
        ConfigFile::parse(base + "[hardware.el]\ndrive = \"pwm\"\n", "c.toml"));
    FAIL() << "[hardware.el] accepted with a fixed elevation";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("[hardware.el]"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)daemon_config_from(ConfigFile::parse(
                   "[station]\ngrid = \"FN06HE\"\n[mount.el]\nfixed_deg = 95.0\n", "c.toml")),
               UsageError);
}

TEST(HardwareConfig, APotOnAnActuatorReadsMillimetresThroughItsTriangle) {
  const DaemonConfig c =
      daemon_config_from(ConfigFile::parse(kTop + testing::kActuatorPotEl, "c.toml"));
  const control::PotInputConfig& pot = c.hardware.el.pot;
  ASSERT_TRUE(pot.actuator.has_value());
  EXPECT_DOUBLE_EQ(pot.actuator->pivot_to_fixed_mm, 650.0);
  EXPECT_DOUBLE_EQ(pot.calibration.deg_b, 977.2);                  // a length here, in millimetres
  EXPECT_NEAR(control::PotInput(pot).push(500).deg, 39.56, 0.01);  // mid-stroke, the page's
}

TEST(HardwareConfig, AnActuatorsMistakesNameTheKey) {
  const auto names = [](const std::string& text, const std::string& key) {
    const std::string e = error_or_empty(text);
    EXPECT_NE(e.find(key), std::string::npos) << text << "\n→ " << e;
  };
  const auto replaced = [](const std::string& from, const std::string& to) {
    std::string t = testing::kActuatorPotEl;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  EXPECT_EQ(error_or_empty(testing::kActuatorPotEl), "");
  // Both lines, or neither: one of them.
  names(testing::kActuatorPotEl + "pot_calibration = [0, 0.0, 1023, 90.0]\n",
        "[hardware.el].pot_calibration");
  names(replaced("pot_calibration_mm = [100, 520.0, 900, 977.2]\n", ""),
        "[hardware.el].pot_calibration");
  names(replaced("actuator_offset_deg = 48.0\n", ""), "[hardware.el].actuator_offset_deg");
  names(replaced("977.2\n", "1200.0\n"), "[hardware.el].actuator_extended_mm");
  // A triangle under a pot calibrated in degrees, or under no sensor of length, does nothing.
  names(replaced("pot_calibration_mm = [100, 520.0, 900, 977.2]",
                 "pot_calibration = [0, 0.0, 1023, 90.0]"),
        "[hardware.el].actuator_pivot_to_fixed_mm is for an actuator's length");
  names("[hardware.az]\nactuator_retracted_mm = 300.0\n", "[hardware.az].actuator_retracted_mm");
}

}  // namespace
}  // namespace azt::app
