// The motor keys: [sim.az] / [sim.el] brake and motor_heating (the plants' and the controller's
// settings, read with [hardware.az]'s own function), and [hardware.az] motor_adc = "ads1115";
// each mistake refused naming its key.
#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"
#include "support/hardware_station.hpp"

namespace azt::app {
namespace {

DaemonConfig sim_config(const std::string& tables) {
  return daemon_config_from(ConfigFile::parse("[station]\ngrid = \"FN06HE\"\n" + tables, "c.toml"));
}

/// The refusal's words, or "" when the file is accepted.
std::string error_of(const std::string& file) {
  try {
    (void)daemon_config_from(ConfigFile::parse(file, "c.toml"));
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

std::string sim_error(const std::string& tables) {
  return error_of("[station]\ngrid = \"FN06HE\"\n" + tables);
}

TEST(SimMotorConfig, TheBrakeIsThePlantsAndItsTimingTheControllers) {
  const DaemonConfig c = sim_config(
      "[sim.az]\nbrake = true\nbrake_lift_s = 2.0\nbrake_hold_s = 0.4\nbrake_release_s = 2.5\n"
      "brake_engage_s = 0.6\nbrake_idle_s = 3.0\n[sim.el]\nbrake = true\n");
  ASSERT_TRUE(c.sim.brakes[0] && c.sim.brakes[1]);
  EXPECT_DOUBLE_EQ(c.sim.brakes[0]->release_s, 2.0);
  EXPECT_DOUBLE_EQ(c.sim.brakes[0]->engage_s, 0.4);
  ASSERT_TRUE(c.sim_motors[0].brake);
  EXPECT_DOUBLE_EQ(c.sim_motors[0].brake->release_s, 2.5);
  EXPECT_DOUBLE_EQ(c.sim_motors[0].brake->engage_s, 0.6);
  EXPECT_DOUBLE_EQ(c.sim_motors[0].brake->idle_s, 3.0);
  // The defaults: the plant's 1.2 s brake, and the controller's as [hardware.az]'s.
  EXPECT_DOUBLE_EQ(c.sim.brakes[1]->release_s, 1.2);
  ASSERT_TRUE(c.sim_motors[1].brake);
  EXPECT_DOUBLE_EQ(c.sim_motors[1].brake->release_s, 1.0);
  EXPECT_DOUBLE_EQ(c.sim_motors[1].brake->idle_s, 2.0);
  EXPECT_FALSE(c.sim_motors[0].trips);
  // What the station is built with.
  const control::StationControlConfig control = sim::station_control_config(c.simulated());
  ASSERT_TRUE(control.az_drive.brake && control.el_drive.brake);
  EXPECT_DOUBLE_EQ(control.az_drive.brake->release_s, 2.5);
  EXPECT_FALSE(control.az_drive.trips);
}

TEST(SimMotorConfig, TheWindingIsThePlantsAndItsTripTheControllers) {
  const DaemonConfig c = sim_config(
      "[sim.el]\nmotor_heating = true\nambient_c = 30.0\nmotor_rise_c = 60.0\n"
      "motor_time_constant_s = 120.0\ntemperature_limit_c = 70.0\n");
  EXPECT_FALSE(c.sim.thermal[0]);
  ASSERT_TRUE(c.sim.thermal[1]);
  EXPECT_DOUBLE_EQ(c.sim.thermal[1]->ambient_c, 30.0);
  EXPECT_DOUBLE_EQ(c.sim.thermal[1]->start_c, 30.0) << "starts at the air's temperature";
  EXPECT_DOUBLE_EQ(c.sim.thermal[1]->rise_at_full_duty_c, 60.0);
  EXPECT_DOUBLE_EQ(c.sim.thermal[1]->time_constant_s, 120.0);
  ASSERT_TRUE(c.sim_motors[1].trips);
  EXPECT_EQ(c.sim_motors[1].trips->axis, "el");
  EXPECT_EQ(c.sim_motors[1].trips->temperature_limit_c, 70.0);
  EXPECT_DOUBLE_EQ(c.sim_motors[1].trips->temperature_hysteresis_c, 5.0);
  EXPECT_FALSE(c.sim_motors[1].trips->current_limit_a) << "the plant has no current sense";
  EXPECT_FALSE(c.sim_motors[1].brake);
  const control::StationControlConfig control = sim::station_control_config(c.simulated());
  EXPECT_TRUE(control.el_drive.trips);
  EXPECT_FALSE(control.az_drive.trips || control.az_drive.brake);
}

TEST(SimMotorConfig, KeysWithoutWhatTheyNeedAreRefusedNamingTheKey) {
  const auto refused = [](const std::string& tables, const std::string& words) {
    const std::string e = sim_error(tables);
    EXPECT_NE(e.find(words), std::string::npos) << tables << " gave: " << e;
  };
  EXPECT_EQ(sim_error("[sim.az]\nbrake = false\n"), "");
  refused("[sim.az]\nbrake_lift_s = 2.0\n", "[sim.az].brake_lift_s needs brake = true");
  refused("[sim.az]\nbrake_release_s = 2.0\n", "[sim.az].brake_release_s needs brake = true");
  refused("[sim.az]\nbrake = true\nbrake_release_s = 0.0\n", "[sim.az].brake_release_s");
  refused("[sim.az]\nbrake = true\nbrake_lift_s = 90.0\n", "[sim.az].brake_lift_s");
  refused("[sim.az]\nmotor_heating = true\n",
          "[sim.az].temperature_limit_c is needed with motor_heating = true");
  refused("[sim.el]\ntemperature_limit_c = 70.0\n",
          "[sim.el].temperature_limit_c needs motor_heating = true");
  refused("[sim.el]\nmotor_rise_c = 70.0\n", "[sim.el].motor_rise_c needs motor_heating = true");
  refused("[sim.az]\nmotor_heating = true\ntemperature_limit_c = 250.0\n",
          "[sim.az].temperature_limit_c");
  refused("[sim.az]\ncurrent_limit_a = 5.0\n", "[sim.az].current_limit_a");
  refused("[mount.pol]\n[sim.pol]\nbrake = true\n", "[sim.pol].brake");
  refused("[mount.el]\nfixed_deg = 10.0\n[sim.el]\nbrake = true\n",
          "[sim.el].brake is for an axis that moves");
}

const std::string kPotOnAds1115 = testing::kHardwareTop + R"([hub]
device = "/dev/null"
[hardware.az]
sensor = "ads1115"
adc_device = "/dev/i2c-1"
adc_address = 73
adc_channel = 0
pot_calibration = [0, 0.0, 26000, 450.0]
)";

TEST(MotorAdcConfig, AnAds1115MotorSharesThePotsChipByDefault) {
  const DaemonConfig c = daemon_config_from(ConfigFile::parse(
      kPotOnAds1115 + "motor_adc = \"ads1115\"\ncurrent_adc_channel = 1\ncurrent_limit_a = 5.0\n"
                      "temperature_adc_channel = 2\ntemperature_limit_c = 70.0\n",
      "c.toml"));
  const HardwareAxisConfig& az = c.hardware.az;
  EXPECT_EQ(az.motor_adc, MotorAdcKind::Ads1115);
  EXPECT_EQ(az.motor_adc_device, "/dev/i2c-1");
  EXPECT_EQ(az.motor_adc_address, 73);
  EXPECT_EQ(az.current_adc_channel, 1U);
  EXPECT_EQ(az.temperature_adc_channel, 2U);
  // Another chip on the same bus.
  const DaemonConfig other = daemon_config_from(ConfigFile::parse(
      kPotOnAds1115 + "motor_adc = \"ads1115\"\nmotor_adc_address = 72\ncurrent_adc_channel = 0\n"
                      "current_limit_a = 5.0\n",
      "c.toml"));
  EXPECT_EQ(other.hardware.az.motor_adc_address, 72);
  EXPECT_EQ(other.hardware.az.current_adc_channel, 0U) << "channel 0 of another chip";
}

TEST(MotorAdcConfig, Ads1115MistakesNameTheKey) {
  const auto refused = [](const std::string& file, const std::string& words) {
    const std::string e = error_of(file);
    EXPECT_NE(e.find(words), std::string::npos) << file << " gave: " << e;
  };
  const std::string ads = kPotOnAds1115 + "motor_adc = \"ads1115\"\n";
  refused(ads + "current_adc_channel = 4\ncurrent_limit_a = 5.0\n",
          "[hardware.az].current_adc_channel must be 0 to 3 on an ADS1115");
  refused(ads + "temperature_adc_channel = 0\ntemperature_limit_c = 70.0\n",
          "[hardware.az].temperature_adc_channel is the pot's channel");
  refused(ads + "motor_adc_address = 80\ncurrent_adc_channel = 1\ncurrent_limit_a = 5.0\n",
          "[hardware.az].motor_adc_address");
  refused(kPotOnAds1115 + "motor_adc = \"ads1116\"\n", "[hardware.az].motor_adc");
  refused(kPotOnAds1115 +
              "motor_adc_address = 72\ncurrent_adc_channel = 1\n"
              "current_limit_a = 5.0\nmotor_adc_device = \"/dev/spidev0.0\"\n",
          "[hardware.az].motor_adc_address is for motor_adc = \"ads1115\"");
  // A pot on an MCP3008 and the motor on an ADS1115: its bus must be named.
  refused(testing::kHardwareTop + "[hub]\ndevice = \"/dev/null\"\n" + testing::kHardwareAz +
              "motor_adc = \"ads1115\"\ncurrent_adc_channel = 1\ncurrent_limit_a = 5.0\n",
          "[hardware.az].motor_adc_device is needed for current_adc_channel / "
          "temperature_adc_channel (an ADS1115's /dev/i2c-N)");
}

}  // namespace
}  // namespace azt::app
