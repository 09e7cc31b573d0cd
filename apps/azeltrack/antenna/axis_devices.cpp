#include "antenna/axis_devices.hpp"

#include <algorithm>
#include <stdexcept>

#include "azt/linux/axis_drives.hpp"
#include "azt/linux/gpio_pulse_input.hpp"
#include "azt/linux/motor_io.hpp"
#include "azt/linux/pwm_hbridge.hpp"
#include "azt/linux/step_dir_drive.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

std::unique_ptr<linux_os::GpioOutput> output_line(HardwarePorts& ports,
                                                  const linux_os::GpioLineSpec& spec) {
  if (ports.gpio == nullptr) throw UsageError(spec.key + ": no GPIO provider");
  auto line = ports.gpio->output(spec, false);  // released until the station asks
  if (!line) throw UsageError(line.error().message);
  return std::move(line).value();
}

/// The ADS1115 at `device` and `address`, opened now or shared with a pot or motor input already
/// on it; `channel` is added to its turns (a slow one: a motor's). `a`'s keys name what fails.
std::shared_ptr<linux_os::Ads1115Chip> ads1115_chip(const HardwareAxisConfig& a,
                                                    const std::string& device, std::uint8_t address,
                                                    unsigned channel, bool slow,
                                                    const std::string& device_key,
                                                    const std::string& channel_key,
                                                    HardwarePorts& ports) {
  std::shared_ptr<linux_os::Ads1115Chip>& chip = ports.ads1115_chips[{device, address}];
  if (!chip) {
    auto bus = ports.open_i2c(device);
    if (!bus) throw UsageError(a.key(device_key) + ": " + bus.error().message);
    chip = std::make_shared<linux_os::Ads1115Chip>(std::move(bus).value(), address);
  } else if (chip->has_channel(channel)) {
    throw UsageError(a.key(channel_key) + ": channel " + std::to_string(channel) +
                     " of this ADS1115 is read already (by another axis's pot or motor)");
  }
  if (slow) {
    chip->add_slow_channel(channel);
  } else {
    chip->add_channel(channel);
  }
  return chip;
}

/// The ADS1115 of `a`'s pot.
std::shared_ptr<linux_os::Ads1115Chip> ads1115_chip(const HardwareAxisConfig& a,
                                                    HardwarePorts& ports) {
  return ads1115_chip(a, a.adc_device, a.adc_address, a.adc_channel, false, "adc_device",
                      "adc_channel", ports);
}

}  // namespace

HardwarePorts HardwarePorts::linux_devices(linux_os::GpioProvider* gpio,
                                           std::chrono::steady_clock::time_point epoch) {
  HardwarePorts p;
  p.gpio = gpio;
  p.epoch = epoch;
  p.open_spi = [](const std::string& path,
                  std::uint32_t hz) -> Result<std::unique_ptr<linux_os::SpiBus>> {
    auto bus = linux_os::SpidevBus::open(path, hz);
    if (!bus) return bus.error();
    return std::unique_ptr<linux_os::SpiBus>(
        std::make_unique<linux_os::SpidevBus>(std::move(bus).value()));
  };
  p.open_i2c = [](const std::string& path) -> Result<std::unique_ptr<linux_os::I2cBus>> {
    auto bus = linux_os::I2cDevBus::open(path);
    if (!bus) return bus.error();
    return std::unique_ptr<linux_os::I2cBus>(
        std::make_unique<linux_os::I2cDevBus>(std::move(bus).value()));
  };
  return p;
}

namespace {

/// "azimuth", "elevation" or "polarisation", for messages.
std::string axis_words(const std::string& name) {
  if (name == "az") return "azimuth";
  return name == "pol" ? "polarisation" : "elevation";
}

std::unique_ptr<ports::AxisDrive> open_relay_drive(const HardwareAxisConfig& a,
                                                   HardwarePorts& ports) {
  const bool pp = a.relay_power.has_value();
  auto first = output_line(ports, pp ? *a.relay_power : *a.relay_forward);
  auto second = output_line(ports, pp ? *a.relay_polarity : *a.relay_reverse);
  std::optional<control::PowerPolarityConfig> power_polarity;
  if (pp)
    power_polarity = control::PowerPolarityConfig{a.relay.reversal_dead_s, a.polarity_settle_s};
  return linux_os::make_relay_lines_drive(
      std::move(first), std::move(second), power_polarity,
      pp ? "relays (power + polarity)" : "relays (forward/reverse)");
}

std::unique_ptr<ports::AxisDrive> open_pot_drive(const HardwareAxisConfig& a,
                                                 HardwarePorts& ports) {
  auto bus = ports.open_spi(a.spi_device, a.spi_hz);
  if (!bus) throw UsageError(a.key("spi_device") + ": " + bus.error().message);
  return linux_os::make_mcp41010_drive(std::move(bus).value(), a.wiper,
                                       "MCP41010 on " + a.spi_device);
}

std::unique_ptr<ports::AxisDrive> open_pwm_drive(const HardwareAxisConfig& a, const PwmConfig& pwm,
                                                 HardwarePorts& ports) {
  auto bridge = linux_os::PwmHBridge::open(pwm.of(a.name));
  if (!bridge) {
    throw UsageError("[pwm] " + axis_words(a.name) + ": " + bridge.error().message);
  }
  std::unique_ptr<linux_os::GpioOutput> enable;
  if (a.enable) {
    try {
      enable = output_line(ports, *a.enable);
    } catch (const UsageError&) {
      (void)bridge.value().disable(0.0);
      throw;
    }
  }
  return linux_os::make_pwm_bridge_drive(
      std::move(bridge).value(), std::move(enable),
      a.enable ? "IBT-2 on sysfs PWM, enables on GPIO" : "IBT-2 on sysfs PWM");
}

/// STEP's channel first (opened at no pulses), then DIR and ENABLE; a line that cannot be had
/// leaves the channel disabled.
std::unique_ptr<ports::AxisDrive> open_step_dir_drive(const HardwareAxisConfig& a,
                                                      HardwarePorts& ports) {
  // The channel starts at the pull-in rate with no pulses; its rate is set at each start.
  auto step =
      linux_os::SysfsPwm::open(a.step_chip, a.step_channel, std::max(a.steps.start_hz, 10.0));
  if (!step) throw UsageError(a.key("step_channel") + ": " + step.error().message);
  std::unique_ptr<linux_os::GpioOutput> dir;
  std::unique_ptr<linux_os::GpioOutput> enable;
  try {
    dir = output_line(ports, *a.step_dir);
    if (a.enable) enable = output_line(ports, *a.enable);
  } catch (const UsageError&) {
    (void)step.value().disable();
    throw;
  }
  return linux_os::make_step_dir_drive(std::move(step).value(), std::move(dir), std::move(enable),
                                       a.steps, "step/dir driver on sysfs PWM and GPIO");
}

}  // namespace

std::unique_ptr<ports::AxisDrive> open_axis_drive(const HardwareAxisConfig& a, const PwmConfig& pwm,
                                                  HardwarePorts& ports) {
  switch (a.drive) {
    case AxisDriveKind::Relay:
      return open_relay_drive(a, ports);
    case AxisDriveKind::Pot:
      return open_pot_drive(a, ports);
    case AxisDriveKind::Pwm:
      return open_pwm_drive(a, pwm, ports);
    case AxisDriveKind::StepDir:
      return open_step_dir_drive(a, ports);
  }
  throw std::logic_error("an axis drive of no known kind");
}

std::unique_ptr<ports::AxisSensor> open_adc_sensor(const HardwareAxisConfig& a,
                                                   HardwarePorts& ports) {
  const std::string what = a.name + " pot (" + std::string(name_of(kAxisSensorKinds, a.sensor)) +
                           " " + a.adc_device + " channel " + std::to_string(a.adc_channel) + ")";
  switch (a.sensor) {
    case AxisSensorKind::Mcp3008: {
      auto bus = ports.open_spi(a.adc_device, 1'000'000);
      if (!bus) throw UsageError(a.key("adc_device") + ": " + bus.error().message);
      return linux_os::make_mcp3008_pot_sensor(std::move(bus).value(), a.adc_channel, a.pot, what);
    }
    case AxisSensorKind::Ads1115:
      return linux_os::make_ads1115_pot_sensor(ads1115_chip(a, ports), a.adc_channel, a.pot, what);
    case AxisSensorKind::Hub:
    case AxisSensorKind::Pulses:
      break;
  }
  throw std::logic_error("the EncoderHub and a pulse sensor are not ADCs: " + what);
}

std::unique_ptr<ports::PulseInput> open_pulse_input(const HardwareAxisConfig& a,
                                                    HardwarePorts& ports) {
  if (ports.gpio == nullptr) throw UsageError(a.key("home_switch") + ": no GPIO provider");
  linux_os::GpioPulseLines lines{a.pulse_lines, *a.home_switch, linux_os::GpioBias::PullUp};
  auto input = linux_os::GpioPulseInput::open(*ports.gpio, lines, ports.epoch);
  if (!input) throw UsageError(input.error().message);
  return std::move(input).value();
}

std::unique_ptr<ports::BrakeLine> open_brake_line(const HardwareAxisConfig& a,
                                                  HardwarePorts& ports) {
  if (!a.brake) return nullptr;
  return linux_os::make_gpio_brake_line(output_line(ports, *a.brake));  // off: braked
}

namespace {

/// "0x48".
std::string hex_address(std::uint8_t address) {
  const char* digits = "0123456789abcdef";
  return std::string("0x") + digits[address >> 4U] + digits[address & 0xFU];
}

/// The ADS1115 of `a`'s current and temperature channels, each a slow channel of the chip.
std::shared_ptr<linux_os::Ads1115Chip> motor_ads1115(const HardwareAxisConfig& a,
                                                     HardwarePorts& ports) {
  std::shared_ptr<linux_os::Ads1115Chip> chip;
  const std::pair<const std::optional<unsigned>*, const char*> inputs[] = {
      {&a.current_adc_channel, "current_adc_channel"},
      {&a.temperature_adc_channel, "temperature_adc_channel"}};
  for (const auto& [channel, key] : inputs) {
    if (*channel) {
      chip = ads1115_chip(a, a.motor_adc_device, a.motor_adc_address, **channel, true,
                          "motor_adc_device", key, ports);
    }
  }
  return chip;
}

}  // namespace

std::unique_ptr<ports::MotorSensor> open_motor_sensor(const HardwareAxisConfig& a,
                                                      HardwarePorts& ports) {
  if (!a.has_motor_inputs()) return nullptr;
  const bool adc_inputs = a.current_adc_channel || a.temperature_adc_channel;
  std::unique_ptr<linux_os::SpiBus> bus;
  std::shared_ptr<linux_os::Ads1115Chip> chip;
  if (adc_inputs) {
    switch (a.motor_adc) {
      case MotorAdcKind::Mcp3008: {
        auto opened = ports.open_spi(a.motor_adc_device, 1'000'000);
        if (!opened) throw UsageError(a.key("motor_adc_device") + ": " + opened.error().message);
        bus = std::move(opened).value();
        break;
      }
      case MotorAdcKind::Ads1115:
        chip = motor_ads1115(a, ports);
        break;
    }
  }
  std::unique_ptr<linux_os::GpioInput> fault;
  if (a.driver_fault) {
    if (ports.gpio == nullptr) throw UsageError(a.driver_fault->key + ": no GPIO provider");
    // Read each tick as the last edge left it: the handler has nothing to do.
    auto line = ports.gpio->input(*a.driver_fault, linux_os::GpioBias::AsIs, [](bool) {});
    if (!line) throw UsageError(line.error().message);
    fault = std::move(line).value();
  }
  linux_os::MotorAdcInputs in;
  in.current_channel = a.current_adc_channel;
  in.current = a.current;
  in.temperature_channel = a.temperature_adc_channel;
  in.temperature_c_per_v = a.temperature_c_per_v;
  in.temperature_offset_c = a.temperature_offset_c;
  if (chip) {
    return linux_os::make_ads1115_motor_sensor(std::move(chip), in, std::move(fault),
                                               a.name + " motor (ADS1115 " + a.motor_adc_device +
                                                   " at " + hex_address(a.motor_adc_address) + ")");
  }
  return linux_os::make_motor_sensor(std::move(bus), in, std::move(fault),
                                     a.name + " motor (MCP3008 " + a.motor_adc_device + ")");
}

}  // namespace azt::app
