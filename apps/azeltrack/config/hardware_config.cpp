#include "config/hardware_config.hpp"

#include <array>
#include <stdexcept>
#include <string_view>

#include "common/usage_error.hpp"
#include "config/actuator_config.hpp"
#include "config/config_file.hpp"
#include "config/motor_keys.hpp"
#include "config/pulse_sensor_config.hpp"

namespace azt::app {

namespace {

/// Whether the axis's pot is read by an MCP3008, whose spare channels may read its motor.
bool pot_on_mcp3008(AxisSensorKind sensor) {
  switch (sensor) {
    case AxisSensorKind::Mcp3008:
      return true;
    case AxisSensorKind::Hub:
    case AxisSensorKind::Ads1115:
    case AxisSensorKind::Pulses:
      return false;
  }
  return false;
}

/// [a, deg_a, b, deg_b]: two measured points (four numbers: the schema).
std::optional<std::array<double, 4>> two_points(const ConfigSection& s, const std::string& key) {
  const toml::array* a = s.array(key);
  if (a == nullptr) return std::nullopt;
  std::array<double, 4> v{};
  for (std::size_t i = 0; i < v.size() && i < a->size(); ++i) v.at(i) = (*a)[i].value_or(0.0);
  return v;
}

void read_relay(const ConfigSection& s, HardwareAxisConfig& a, const std::string& chip) {
  const bool low = s.boolean("relay_active_low").value_or(false);
  a.relay_forward = read_gpio_line(s, "relay_forward", chip, low);
  a.relay_reverse = read_gpio_line(s, "relay_reverse", chip, low);
  a.relay_power = read_gpio_line(s, "relay_power", chip, low);
  a.relay_polarity = read_gpio_line(s, "relay_polarity", chip, low);
  const bool pair = a.relay_forward || a.relay_reverse;
  const bool power = a.relay_power || a.relay_polarity;
  if (pair == power || (pair && !(a.relay_forward && a.relay_reverse)) ||
      (power && !(a.relay_power && a.relay_polarity))) {
    s.fail("drive",
           "is \"relay\": give relay_forward and relay_reverse, or relay_power and "
           "relay_polarity");
  }
  control::RelayDriveConfig r;
  r.window_deg = s.number("window_deg").value_or(r.window_deg);
  r.lsb_deg = s.number("lsb_deg").value_or(r.lsb_deg);
  r.coast_deg = s.number("coast_deg").value_or(r.coast_deg);
  r.min_on_s = s.number("min_on_s").value_or(r.min_on_s);
  r.reversal_dead_s = s.number("reversal_dead_s").value_or(r.reversal_dead_s);
  auto checked = control::RelayDriveConfig::make(r);
  if (!checked) s.fail("drive", "relay settings: " + checked.error().message);
  a.relay = *checked;
  a.polarity_settle_s = s.number("polarity_settle_s").value_or(a.polarity_settle_s);
  if (!control::PowerPolarityConfig::make({a.relay.reversal_dead_s, a.polarity_settle_s})) {
    s.fail("polarity_settle_s", "must be 0 to 1 s");
  }
}

void read_pot_drive(const ConfigSection& s, HardwareAxisConfig& a) {
  a.spi_device = s.text("spi_device").value_or("");
  if (a.spi_device.empty()) s.fail("spi_device", "is needed for drive = \"pot\" (/dev/spidevB.C)");
  a.spi_hz = static_cast<std::uint32_t>(s.integer("spi_hz").value_or(a.spi_hz));
  const auto w = two_points(s, "wiper_calibration");
  if (!w)
    s.fail("wiper_calibration", "is needed for drive = \"pot\": [wiper_a, deg_a, wiper_b, deg_b]");
  auto cal = control::SetpointCalibration::make((*w)[0], (*w)[1], (*w)[2], (*w)[3]);
  if (!cal) s.fail("wiper_calibration", cal.error().message);
  a.wiper = *cal;
  a.setpoint_band_deg = s.number("setpoint_band_deg").value_or(a.setpoint_band_deg);
}

/// What reading a pot through each converter needs.
struct AdcKind {
  std::string_view device_needed;
  unsigned channels = 0;
  control::AdcSpec spec;
};

AdcKind adc_kind(AxisSensorKind sensor) {
  // The ADS1115 at ±4.096 V reads a 3.3 V pot in 15 bits; the MCP3008 is 10 bits of its VREF.
  switch (sensor) {
    case AxisSensorKind::Mcp3008:
      return {"is needed for sensor = \"mcp3008\" (/dev/spidevB.C)", 8, {10, 3.3}};
    case AxisSensorKind::Ads1115:
      return {"is needed for sensor = \"ads1115\" (/dev/i2c-N)", 4, {15, 4.096}};
    case AxisSensorKind::Hub:
    case AxisSensorKind::Pulses:
      break;
  }
  throw std::logic_error("the EncoderHub and a pulse sensor are not ADCs");
}

/// pot_calibration (two readings at known angles), or pot_calibration_mm (two at known actuator
/// lengths) with the actuator's triangle: one of them.
void read_pot_line(const ConfigSection& s, control::PotInputConfig& pot) {
  const auto deg = two_points(s, "pot_calibration");
  const auto mm = two_points(s, "pot_calibration_mm");
  if (deg.has_value() == mm.has_value()) {
    s.fail("pot_calibration",
           "an ADC sensor needs pot_calibration [counts_a, deg_a, counts_b, deg_b] read at two "
           "angles, or on a linear actuator pot_calibration_mm [counts_a, mm_a, counts_b, mm_b] "
           "read at two lengths with the actuator_* triangle: one of them");
  }
  const auto& p = deg ? *deg : *mm;
  const char* key = deg ? "pot_calibration" : "pot_calibration_mm";
  auto cal = control::PotCalibration::make(p[0], p[1], p[2], p[3]);
  if (!cal) s.fail(key, cal.error().message);
  pot.calibration = *cal;
  if (mm) pot.actuator = read_actuator(s, "pot_calibration_mm");
}

void read_adc(const ConfigSection& s, HardwareAxisConfig& a) {
  const AdcKind kind = adc_kind(a.sensor);
  a.adc_device = s.text("adc_device").value_or("");
  if (a.adc_device.empty()) s.fail("adc_device", std::string(kind.device_needed));
  const auto ch = s.integer("adc_channel").value_or(0);  // 0 to 7 (the schema)
  if (ch >= kind.channels)
    s.fail("adc_channel", "must be 0 to " + std::to_string(kind.channels - 1));
  a.adc_channel = static_cast<unsigned>(ch);
  a.adc_address = static_cast<std::uint8_t>(s.integer("adc_address").value_or(0x48));
  a.pot.adc = kind.spec;
  read_pot_line(s, a.pot);
  // Checked before narrowing: 4294967297 must be an error, never 1.
  const std::int64_t max_counts = std::int64_t{1} << a.pot.adc.bits;
  if (const auto lo = s.integer("open_below_counts")) {
    if (*lo < 0 || *lo > max_counts) s.fail("open_below_counts", "must be 0 to the ADC's range");
    a.pot.open_below_counts = static_cast<std::int32_t>(*lo);
  }
  if (const auto hi = s.integer("open_above_counts")) {
    if (*hi < 0 || *hi > max_counts) s.fail("open_above_counts", "must be 0 to the ADC's range");
    a.pot.open_above_counts = static_cast<std::int32_t>(*hi);
  }
  a.pot.average_samples = static_cast<std::size_t>(s.integer("average_samples").value_or(4));
  if (auto ok = control::PotInputConfig::make(a.pot); !ok)
    s.fail(a.pot.actuator ? "pot_calibration_mm" : "pot_calibration", ok.error().message);
}

void refuse_enable(const ConfigSection& s, const HardwareAxisConfig& a) {
  if (a.enable) {
    s.fail("enable", "is for drive = \"pwm\" (the IBT-2's enables) or \"stepdir\" (the driver's)");
  }
}

void read_step_dir(const ConfigSection& s, HardwareAxisConfig& a, const std::string& chip) {
  if (!s.has("step_channel")) s.fail("step_channel", "is needed by drive = \"stepdir\" (STEP)");
  a.step_channel = static_cast<unsigned>(*s.integer("step_channel"));
  a.step_chip = s.text("step_chip").value_or(a.step_chip);
  a.step_dir = read_gpio_line(s, "dir", chip, false);
  if (!a.step_dir) s.fail("dir", "is needed by drive = \"stepdir\" (the driver's DIR)");
  const control::StepDirConfig d;
  auto steps = control::StepDirConfig::make(s.number("max_step_hz").value_or(d.max_step_hz),
                                            s.number("start_step_hz").value_or(d.start_hz),
                                            s.number("step_accel_hz_s").value_or(d.accel_hz_s));
  if (!steps) s.fail("start_step_hz", steps.error().message);
  a.steps = *steps;
}

void read_brake(const ConfigSection& s, HardwareAxisConfig& a, const std::string& chip) {
  a.brake = read_gpio_line(s, "brake", chip, s.boolean("brake_active_low").value_or(false));
  a.brake_timing = read_brake_timing(s);
}

/// Whether the axis's pot is read by an ADS1115, whose spare channels may read its motor.
bool pot_on_ads1115(AxisSensorKind sensor) {
  switch (sensor) {
    case AxisSensorKind::Ads1115:
      return true;
    case AxisSensorKind::Hub:
    case AxisSensorKind::Mcp3008:
    case AxisSensorKind::Pulses:
      return false;
  }
  return false;
}

/// Whether the axis's pot is read by the kind of converter its motor channels are on (motor_adc),
/// whose spare channels may then read them.
bool pot_on_motor_adc(const HardwareAxisConfig& a) {
  switch (a.motor_adc) {
    case MotorAdcKind::Mcp3008:
      return pot_on_mcp3008(a.sensor);
    case MotorAdcKind::Ads1115:
      return pot_on_ads1115(a.sensor);
  }
  return false;
}

/// A current or temperature channel: 0 to 7 on an MCP3008 (the schema), 0 to 3 on an ADS1115.
std::optional<unsigned> motor_channel(const ConfigSection& s, const std::string& key,
                                      MotorAdcKind adc) {
  if (!s.has(key)) return std::nullopt;
  const auto ch = static_cast<unsigned>(s.integer(key).value_or(0));
  if (adc == MotorAdcKind::Ads1115 && ch > 3) s.fail(key, "must be 0 to 3 on an ADS1115");
  return ch;
}

/// The converter of the current and temperature channels: by default the pot's own when it is
/// of motor_adc's kind (its device, and an ADS1115's address), on other channels than the pot's.
void read_motor_adc(const ConfigSection& s, HardwareAxisConfig& a) {
  const bool ads1115 = a.motor_adc == MotorAdcKind::Ads1115;
  if (!ads1115 && s.has("motor_adc_address")) {
    s.fail("motor_adc_address", "is for motor_adc = \"ads1115\"");
  }
  a.motor_adc_address =
      static_cast<std::uint8_t>(s.integer("motor_adc_address").value_or(a.adc_address));
  const bool pot_adc_shareable = pot_on_motor_adc(a);
  a.motor_adc_device = s.text("motor_adc_device").value_or(pot_adc_shareable ? a.adc_device : "");
  if (a.motor_adc_device.empty()) {
    s.fail("motor_adc_device",
           ads1115 ? "is needed for current_adc_channel / temperature_adc_channel (an ADS1115's "
                     "/dev/i2c-N) unless the axis's pot is on an ADS1115"
                   : "is needed for current_adc_channel / temperature_adc_channel (an MCP3008's "
                     "/dev/spidevB.C) unless the axis's pot is on an MCP3008");
  }
  const bool shares_pot_adc = pot_adc_shareable && a.motor_adc_device == a.adc_device &&
                              (!ads1115 || a.motor_adc_address == a.adc_address);
  for (const char* key : {"current_adc_channel", "temperature_adc_channel"}) {
    const auto ch = motor_channel(s, key, a.motor_adc);
    if (ch && shares_pot_adc && *ch == a.adc_channel) {
      s.fail(key, "is the pot's channel (adc_channel)");
    }
  }
  if (a.current_adc_channel && a.current_adc_channel == a.temperature_adc_channel) {
    s.fail("temperature_adc_channel", "is the current's channel");
  }
}

/// The current and temperature inputs, their limits, and the driver's fault line.
void read_motor_inputs(const ConfigSection& s, HardwareAxisConfig& a, const std::string& chip) {
  a.motor_adc = s.choice("motor_adc", kMotorAdcKinds, MotorAdcKind::Mcp3008);
  a.current_adc_channel = motor_channel(s, "current_adc_channel", a.motor_adc);
  a.temperature_adc_channel = motor_channel(s, "temperature_adc_channel", a.motor_adc);
  a.driver_fault =
      read_gpio_line(s, "driver_fault", chip, s.boolean("driver_fault_active_low").value_or(false));
  a.trips.axis = a.name;
  a.current.amps_per_volt = s.number("amps_per_volt").value_or(a.current.amps_per_volt);
  a.current.offset_v = s.number("current_offset_v").value_or(a.current.offset_v);
  if (auto c = control::CurrentSense::make(a.current); !c) {
    fail_field(s, c.error().message.starts_with("offset_v") ? "current_" : "", c.error().message);
  }
  a.trips.current_trip_s = s.number("current_trip_s").value_or(a.trips.current_trip_s);
  read_temperature_hysteresis(s, a.trips);
  a.temperature_c_per_v = s.number("temperature_c_per_v").value_or(a.temperature_c_per_v);
  a.temperature_offset_c = s.number("temperature_offset_c").value_or(a.temperature_offset_c);
  a.trips.current_limit_a = read_trip_limit(s, "current_limit_a", a.current_adc_channel.has_value(),
                                            "current_adc_channel", "the IS pin's ADC input");
  a.trips.temperature_limit_c =
      read_trip_limit(s, "temperature_limit_c", a.temperature_adc_channel.has_value(),
                      "temperature_adc_channel", "the sensor's ADC input");
  if (auto t = control::MotorTripsConfig::make(a.trips); !t) fail_field(s, "", t.error().message);
  if (a.current_adc_channel || a.temperature_adc_channel) read_motor_adc(s, a);
}

}  // namespace

HardwareAxisConfig read_hardware_axis(const ConfigSection& s, const std::string& name,
                                      const std::string& chip) {
  HardwareAxisConfig a;
  a.name = name;
  a.drive = s.choice("drive", kAxisDriveKinds, AxisDriveKind::Pwm);
  a.sensor = s.choice("sensor", kAxisSensorKinds, AxisSensorKind::Hub);
  a.enable = read_gpio_line(s, "enable", chip, false);
  switch (a.drive) {
    case AxisDriveKind::Pwm:
      break;
    case AxisDriveKind::Relay:
      refuse_enable(s, a);
      read_relay(s, a, chip);
      break;
    case AxisDriveKind::Pot:
      refuse_enable(s, a);
      read_pot_drive(s, a);
      break;
    case AxisDriveKind::StepDir:
      read_step_dir(s, a, chip);
      break;
  }
  if (read_by_adc(a.sensor)) read_adc(s, a);
  read_pulse_sensor(s, a, chip);
  if (!a.pot.actuator && !(a.pulses && a.pulses->geometry)) refuse_actuator_keys(s);
  read_brake(s, a, chip);
  read_motor_inputs(s, a, chip);
  return a;
}

void fail_field(const ConfigSection& s, const std::string& prefix, const std::string& message) {
  const auto space = message.find(' ');
  s.fail(prefix + message.substr(0, space), message.substr(space + 1));
}

/// A line is a number on [gpio] chip, or "CHIP:N" for a line on another chip.
std::optional<linux_os::GpioLineSpec> read_gpio_line(const ConfigSection& s, const std::string& key,
                                                     const std::string& chip, bool active_low) {
  if (!s.has(key)) return std::nullopt;
  linux_os::GpioLineSpec spec{chip, 0, active_low, "[" + s.name() + "] " + key};
  // The schema has checked the form: 0 to 1023, or "CHIP:N" with N in that range.
  if (s.is_text(key)) {
    const std::string text = *s.text(key);
    const auto colon = text.rfind(':');
    spec.chip = text.substr(0, colon);
    spec.offset = static_cast<unsigned>(std::stoul(text.substr(colon + 1)));
  } else {
    spec.offset = static_cast<unsigned>(s.integer(key).value_or(0));
  }
  return spec;
}

HardwareAxisConfig default_axis(const std::string& name) {
  HardwareAxisConfig a;
  a.name = name;
  return a;
}

HardwareConfig read_hardware(const ConfigFile& file, const std::string& gpio_chip, bool el_axis) {
  const ConfigSection hw = file.section("hardware");
  HardwareConfig h;
  h.az = read_hardware_axis(hw.child("az"), "az", gpio_chip);
  h.el = read_hardware_axis(hw.child("el"), "el", gpio_chip);
  // A fixed elevation ([mount.el] fixed_deg) has nothing to drive or read.
  h.el_axis = el_axis;
  if (!h.el_axis && hw.child("el").present()) {
    file.fail(
        "[hardware.el] drives an elevation that [mount.el] fixed_deg says does not move: "
        "remove the table");
  }
  if (const ConfigSection pol = hw.child("pol"); pol.present()) {
    if (!pol.has("sensor")) {
      pol.fail("sensor",
               "is needed: a pot on an ADC (\"mcp3008\" or \"ads1115\") or a pulse count "
               "(\"pulses\"); the EncoderHub reads azimuth and elevation only");
    }
    h.pol = read_hardware_axis(pol, "pol", gpio_chip);
    // The hub's frames carry two angles (docs/encoder-hub.md): there is no third to read.
    if (read_by_hub(h.pol->sensor)) {
      pol.fail("sensor",
               "is \"hub\", but the EncoderHub reads azimuth and elevation only: read the pol "
               "axis with a pot on an ADC (sensor = \"mcp3008\" or \"ads1115\") or its pulses");
    }
  }
  const ConfigSection power = hw.child("power");
  if (auto relay =
          read_gpio_line(power, "relay", gpio_chip, power.boolean("active_low").value_or(false))) {
    h.power = MotorPowerConfig{*relay, power.number("on_lead_s").value_or(5.0)};
  }
  return h;
}

}  // namespace azt::app
