#include "config/hardware_config.hpp"

#include <array>

#include "common/usage_error.hpp"
#include "config/config_file.hpp"

namespace azt::app {

namespace {

/// [a, deg_a, b, deg_b]: two measured points.
std::optional<std::array<double, 4>> two_points(const ConfigSection& s, const std::string& key) {
  const toml::array* a = s.array(key);
  if (a == nullptr) return std::nullopt;
  std::array<double, 4> v{};
  if (a->size() != 4) s.fail(key, "must be [code_a, deg_a, code_b, deg_b]");
  for (std::size_t i = 0; i < 4; ++i) {
    const auto x = (*a)[i].value<double>();
    if (!x) s.fail(key, "must hold four numbers");
    v.at(i) = *x;
  }
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
  const auto hz = s.integer("spi_hz").value_or(a.spi_hz);
  if (hz < 10'000 || hz > 10'000'000) s.fail("spi_hz", "must be 10000 to 10000000");
  a.spi_hz = static_cast<std::uint32_t>(hz);
  const auto w = two_points(s, "wiper_calibration");
  if (!w)
    s.fail("wiper_calibration", "is needed for drive = \"pot\": [wiper_a, deg_a, wiper_b, deg_b]");
  auto cal = control::SetpointCalibration::make((*w)[0], (*w)[1], (*w)[2], (*w)[3]);
  if (!cal) s.fail("wiper_calibration", cal.error().message);
  a.wiper = *cal;
  a.setpoint_band_deg = s.number("setpoint_band_deg").value_or(a.setpoint_band_deg);
  if (a.setpoint_band_deg <= 0.0 || a.setpoint_band_deg > 20.0)
    s.fail("setpoint_band_deg", "must be above 0 and at most 20");
}

void read_adc(const ConfigSection& s, HardwareAxisConfig& a) {
  a.adc_device = s.text("adc_device").value_or("");
  if (a.adc_device.empty()) {
    s.fail("adc_device", a.sensor == AxisSensorKind::Mcp3008
                             ? "is needed for sensor = \"mcp3008\" (/dev/spidevB.C)"
                             : "is needed for sensor = \"ads1115\" (/dev/i2c-N)");
  }
  const unsigned channels = a.sensor == AxisSensorKind::Mcp3008 ? 8 : 4;
  const auto ch = s.integer("adc_channel").value_or(0);
  if (ch < 0 || ch >= channels)
    s.fail("adc_channel", "must be 0 to " + std::to_string(channels - 1));
  a.adc_channel = static_cast<unsigned>(ch);
  const auto addr = s.integer("adc_address").value_or(0x48);
  if (addr < 0x48 || addr > 0x4B) s.fail("adc_address", "must be 72 to 75 (0x48–0x4B)");
  a.adc_address = static_cast<std::uint8_t>(addr);
  // The ADS1115 at ±4.096 V reads a 3.3 V pot in 15 bits; the MCP3008 is 10 bits of its VREF.
  a.pot.adc =
      a.sensor == AxisSensorKind::Mcp3008 ? control::AdcSpec{10, 3.3} : control::AdcSpec{15, 4.096};
  const auto p = two_points(s, "pot_calibration");
  if (!p) {
    s.fail("pot_calibration",
           "is needed for an ADC sensor: [counts_a, deg_a, counts_b, deg_b] read at two angles");
  }
  auto cal = control::PotCalibration::make((*p)[0], (*p)[1], (*p)[2], (*p)[3]);
  if (!cal) s.fail("pot_calibration", cal.error().message);
  a.pot.calibration = *cal;
  // Checked before narrowing: 4294967297 must be an error, never 1 (issue 12 row 9).
  const std::int64_t max_counts = std::int64_t{1} << a.pot.adc.bits;
  if (const auto lo = s.integer("open_below_counts")) {
    if (*lo < 0 || *lo > max_counts) s.fail("open_below_counts", "must be 0 to the ADC's range");
    a.pot.open_below_counts = static_cast<std::int32_t>(*lo);
  }
  if (const auto hi = s.integer("open_above_counts")) {
    if (*hi < 0 || *hi > max_counts) s.fail("open_above_counts", "must be 0 to the ADC's range");
    a.pot.open_above_counts = static_cast<std::int32_t>(*hi);
  }
  const auto samples = s.integer("average_samples").value_or(4);
  if (samples < 1 || samples > static_cast<std::int64_t>(control::MovingAverage::kCapacity)) {
    s.fail("average_samples", "must be 1 to " + std::to_string(control::MovingAverage::kCapacity));
  }
  a.pot.average_samples = static_cast<std::size_t>(samples);
  if (auto ok = control::PotInputConfig::make(a.pot); !ok)
    s.fail("pot_calibration", ok.error().message);
}

HardwareAxisConfig read_axis(const ConfigSection& s, const std::string& name,
                             const std::string& chip) {
  HardwareAxisConfig a;
  a.name = name;
  const auto drive = choose(kAxisDriveKinds, s.text("drive").value_or("pwm"));
  if (!drive)
    s.fail("drive", "must be \"pwm\" (IBT-2 on [pwm]), \"relay\" (GPIO) or \"pot\" (MCP41010)");
  a.drive = *drive;
  const auto sensor = choose(kAxisSensorKinds, s.text("sensor").value_or("hub"));
  if (!sensor)
    s.fail("sensor", "must be \"hub\" (EncoderHub on [hub]), \"mcp3008\" or \"ads1115\"");
  a.sensor = *sensor;
  a.enable = read_gpio_line(s, "enable", chip, false);
  if (a.enable && a.drive != AxisDriveKind::Pwm)
    s.fail("enable", "is for drive = \"pwm\" (the IBT-2's enables)");
  if (a.drive == AxisDriveKind::Relay) read_relay(s, a, chip);
  if (a.drive == AxisDriveKind::Pot) read_pot_drive(s, a);
  if (a.sensor != AxisSensorKind::Hub) read_adc(s, a);
  return a;
}

}  // namespace

/// A line is a number on [gpio] chip, or "CHIP:N" for a line on another chip.
std::optional<linux_os::GpioLineSpec> read_gpio_line(const ConfigSection& s, const std::string& key,
                                                     const std::string& chip, bool active_low) {
  if (!s.has(key)) return std::nullopt;
  linux_os::GpioLineSpec spec{chip, 0, active_low, "[" + s.name() + "] " + key};
  std::int64_t offset = -1;
  if (s.is_text(key)) {
    const auto text = s.text(key);
    const auto colon = text->rfind(':');
    if (colon == std::string::npos || colon == 0)
      s.fail(key, "must be a line number or \"CHIP:N\"");
    spec.chip = text->substr(0, colon);
    try {
      std::size_t used = 0;
      offset = std::stoll(text->substr(colon + 1), &used);
      if (used != text->size() - colon - 1) offset = -1;
    } catch (const std::exception&) {
      offset = -1;
    }
  } else {
    offset = s.integer(key).value_or(-1);
  }
  if (offset < 0 || offset > 1023) s.fail(key, "must be a line number 0 to 1023, or \"CHIP:N\"");
  spec.offset = static_cast<unsigned>(offset);
  return spec;
}

HardwareAxisConfig default_axis(const std::string& name) {
  HardwareAxisConfig a;
  a.name = name;
  return a;
}

HardwareConfig read_hardware(const ConfigFile& file, const std::string& gpio_chip) {
  const ConfigSection hw = file.section("hardware", {"az", "el"});
  const std::initializer_list<std::string_view> keys = {"drive",
                                                        "sensor",
                                                        "relay_forward",
                                                        "relay_reverse",
                                                        "relay_power",
                                                        "relay_polarity",
                                                        "relay_active_low",
                                                        "window_deg",
                                                        "lsb_deg",
                                                        "coast_deg",
                                                        "min_on_s",
                                                        "reversal_dead_s",
                                                        "polarity_settle_s",
                                                        "spi_device",
                                                        "spi_hz",
                                                        "wiper_calibration",
                                                        "setpoint_band_deg",
                                                        "adc_device",
                                                        "adc_channel",
                                                        "adc_address",
                                                        "pot_calibration",
                                                        "open_below_counts",
                                                        "open_above_counts",
                                                        "average_samples"};
  HardwareConfig h;
  h.az = read_axis(hw.child("az", keys), "az", gpio_chip);
  h.el = read_axis(hw.child("el", keys), "el", gpio_chip);
  return h;
}

}  // namespace azt::app
