// sensor = "pulses" on [hardware.az] / [hardware.el] / [hardware.pol] (docs/hardware.md, "Pulse
// sensors and homing"): a reed, Hall or quadrature sensor, its home switch, its scale in degrees
// or through an actuator's triangle, and its homing; every mistake refused naming its key.
#include <gtest/gtest.h>

#include <string>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {
namespace {

const std::string kTop =
    "[station]\ngrid = \"FN06HE\"\n[antenna]\nbackend = \"hardware\"\n[hub]\ndevice = "
    "\"/dev/null\"\n";

/// Azimuth on relays, counted by a reed on line 12 from a home switch on line 13.
const std::string kReedAz = R"([hardware.az]
drive = "relay"
relay_forward = 5
relay_reverse = 6
sensor = "pulses"
pulse_line = 12
home_switch = 13
counts_per_deg = 11.7
home_deg = 5.0
)";

/// The elevation of a dish on an 18-inch actuator (docs/hardware.md, "Linear actuators").
const std::string kActuatorEl = R"([hardware.el]
drive = "relay"
relay_forward = 7
relay_reverse = 8
sensor = "pulses"
pulse_a = 20
pulse_b = 21
pulse_reversed = true
home_switch = 22
home_active_low = true
counts_per_mm = 4.0
home_mm = 320.0
actuator_pivot_to_fixed_mm = 500.0
actuator_pivot_to_moving_mm = 420.0
actuator_offset_deg = 30.0
actuator_retracted_mm = 300.0
actuator_extended_mm = 757.2
home_seek_duty = -0.8
home_tolerance_counts = 2
home_at_start = false
)";

DaemonConfig load(const std::string& text) {
  return daemon_config_from(ConfigFile::parse(kTop + text, "c.toml"));
}

std::string error_of(const std::string& text) {
  try {
    (void)load(text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(PulseSensorConfig, AReedOnARotatorCountsDegreesFromItsSwitch) {
  const DaemonConfig c = load(kReedAz);
  const HardwareAxisConfig& az = c.hardware.az;
  ASSERT_TRUE(az.pulses.has_value());
  ASSERT_EQ(az.pulse_lines.size(), 1U);
  EXPECT_EQ(az.pulse_lines[0].offset, 12U);
  ASSERT_TRUE(az.home_switch.has_value());
  EXPECT_EQ(az.home_switch->offset, 13U);
  EXPECT_EQ(az.pulses->counter.kind, control::PulseInputKind::SingleChannel);
  EXPECT_EQ(az.pulses->scale.unit, control::PulseUnit::Degrees);
  EXPECT_DOUBLE_EQ(az.pulses->scale.counts_per_unit, 11.7);
  EXPECT_DOUBLE_EQ(az.pulses->scale.home_value, 5.0);
  EXPECT_FALSE(az.pulses->geometry.has_value());
  EXPECT_TRUE(az.pulses->home_at_start);
  // The pulse line and the switch join the lines checked against every other use.
  EXPECT_EQ(az.gpio_lines().size(), 4U);
  EXPECT_TRUE(control::PulseAxis::make(*az.pulses).ok());
}

TEST(PulseSensorConfig, AQuadratureActuatorCountsMillimetresThroughItsTriangle) {
  const DaemonConfig c = load(kActuatorEl);
  const HardwareAxisConfig& el = c.hardware.el;
  ASSERT_TRUE(el.pulses.has_value());
  ASSERT_EQ(el.pulse_lines.size(), 2U);
  EXPECT_EQ(el.pulse_lines[1].offset, 21U);
  EXPECT_TRUE(el.home_switch->active_low);
  EXPECT_EQ(el.pulses->counter.kind, control::PulseInputKind::Quadrature);
  EXPECT_TRUE(el.pulses->counter.reversed);
  EXPECT_EQ(el.pulses->scale.unit, control::PulseUnit::Millimetres);
  ASSERT_TRUE(el.pulses->geometry.has_value());
  EXPECT_DOUBLE_EQ(el.pulses->geometry->pivot_to_moving_mm, 420.0);
  EXPECT_DOUBLE_EQ(el.pulses->homing.seek_duty, -0.8);
  EXPECT_EQ(el.pulses->homing.tolerance_counts, 2);
  EXPECT_FALSE(el.pulses->home_at_start);
  EXPECT_TRUE(control::PulseAxis::make(*el.pulses).ok());
}

TEST(PulseSensorConfig, MistakesNameTheKey) {
  const auto names = [](const std::string& text, const std::string& key) {
    const std::string e = error_of(text);
    EXPECT_NE(e.find(key), std::string::npos) << text << "\n→ " << e;
  };
  const auto without = [](const std::string& line) {
    std::string t = kReedAz;
    t.erase(t.find(line), line.size() + 1);
    return t;
  };
  names(without("home_switch = 13"), "[hardware.az].home_switch");
  names(without("counts_per_deg = 11.7"), "[hardware.az].counts_per_deg");
  names(kReedAz + "counts_per_mm = 2.0\n", "[hardware.az].counts_per_deg");
  names(kReedAz + "pulse_a = 20\n", "[hardware.az].pulse_line");
  names(kReedAz + "pulse_reversed = true\n", "[hardware.az].pulse_reversed");
  names(kReedAz + "home_seek_duty = 0.0\n", "[hardware.az].home_seek_duty");
  names(kReedAz + "home_mm = 300.0\n", "[hardware.az].home_mm");
  // The pulse line may not be a relay's, nor the E-stop's.
  names(without("pulse_line = 12") + "pulse_line = 6\n", "is the same line as");
  // A setpoint box closes its loop on its own pot: it cannot follow a count.
  names(R"([hardware.az]
drive = "pot"
spi_device = "/dev/spidev0.0"
wiper_calibration = [0, 0.0, 255, 450.0]
sensor = "pulses"
pulse_line = 12
home_switch = 13
counts_per_deg = 2.0
)",
        "[hardware.az].sensor");
  // A home switch under a pot sensor would do nothing: refused rather than ignored.
  names(R"([hardware.az]
sensor = "mcp3008"
adc_device = "/dev/spidev0.1"
pot_calibration = [0, 0.0, 1023, 450.0]
home_switch = 13
)",
        "[hardware.az].home_switch");
  // The actuator: every side of the triangle, and a stroke the triangle allows.
  std::string no_side = kActuatorEl;
  no_side.erase(no_side.find("actuator_offset_deg"),
                std::string("actuator_offset_deg = 30.0\n").size());
  names(no_side, "[hardware.el].actuator_offset_deg");
  std::string too_long = kActuatorEl;
  too_long.replace(too_long.find("757.2"), 5, "950.0");
  names(too_long, "[hardware.el].actuator_extended_mm");
  std::string home_outside = kActuatorEl;
  home_outside.replace(home_outside.find("home_mm = 320.0"), 15, "home_mm = 200.0");
  names(home_outside, "[hardware.el].home_mm");
}

/// A feed rotator on relays, counted by a reed on line 14 from a home switch on line 15.
const std::string kReedPol = R"([mount.pol]
[hardware.pol]
drive = "relay"
relay_forward = 7
relay_reverse = 8
sensor = "pulses"
pulse_line = 14
home_switch = 15
counts_per_deg = 2.0
home_deg = -90.0
home_at_start = false
)";

TEST(PulseSensorConfig, ThePolarisationAxisCountsPulsesAsAzAndElDo) {
  const DaemonConfig c = load(kReedPol);
  ASSERT_TRUE(c.hardware.pol.has_value());
  const HardwareAxisConfig& pol = *c.hardware.pol;
  ASSERT_TRUE(pol.pulses.has_value());
  EXPECT_EQ(pol.pulse_lines.at(0).offset, 14U);
  EXPECT_EQ(pol.home_switch->offset, 15U);
  EXPECT_DOUBLE_EQ(pol.pulses->scale.home_value, -90.0);
  EXPECT_FALSE(pol.pulses->home_at_start);
  EXPECT_EQ(pol.gpio_lines().size(), 4U);
  EXPECT_TRUE(control::PulseAxis::make(*pol.pulses).ok());
}

TEST(PulseSensorConfig, ThePolarisationAxisIsRefusedAsAzAndElAre) {
  const auto names = [](const std::string& text, const std::string& key) {
    const std::string e = error_of(text);
    EXPECT_NE(e.find(key), std::string::npos) << text << "\n→ " << e;
  };
  const auto with = [](const std::string& line, const std::string& instead) {
    std::string t = kReedPol;
    t.replace(t.find(line), line.size(), instead);
    return t;
  };
  names(with("home_switch = 15\n", ""), "[hardware.pol].home_switch");
  names(with("counts_per_deg = 2.0", "pulse_a = 20"), "[hardware.pol].pulse_line");
  names(with("drive = \"relay\"",
             "drive = \"pot\"\nspi_device = \"/dev/spidev0.0\"\n"
             "wiper_calibration = [0, -95.0, 255, 95.0]"),
        "[hardware.pol].sensor");
  // Its lines join the check of every line: its own relay's, the azimuth's count, the E-stop.
  names(with("pulse_line = 14", "pulse_line = 7"), "is the same line as");
  names(kReedAz + with("home_switch = 15", "home_switch = 12"), "is the same line as");
  names(kReedPol + "[gpio]\nestop = 14\n", "is the same line as");
  // The hub's frames carry two angles: never the pol axis's.
  names(with("sensor = \"pulses\"", "sensor = \"hub\""), "[hardware.pol].sensor must be");
}

}  // namespace
}  // namespace azt::app
