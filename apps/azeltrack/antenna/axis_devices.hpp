#pragma once
// Opening one axis's devices for the `hardware` backend from [hardware.az|el|pol]: what moves it
// (an IBT-2 bridge on sysfs PWM, relays on GPIO lines, or an MCP41010 in a rotator box) and what
// reads it (a potentiometer on an MCP3008 or ADS1115; the EncoderHub reads both axes at once).
// The devices themselves are platform/linux's, behind the core's ports; they are opened through
// HardwarePorts, so tests put simulated buses behind them.

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "azt/linux/gpio.hpp"
#include "azt/linux/i2c_device.hpp"
#include "azt/linux/pot_sensors.hpp"
#include "azt/linux/spi_device.hpp"
#include "azt/ports/axis_drive.hpp"
#include "azt/ports/axis_sensor.hpp"
#include "azt/ports/motor_io.hpp"
#include "azt/ports/pulse_input.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {

struct HardwarePorts {
  linux_os::GpioProvider* gpio = nullptr;  ///< needed by relay drives
  /// The control loop's time zero: a pulse edge's kernel timestamp is placed on its clock.
  std::chrono::steady_clock::time_point epoch{};
  std::function<Result<std::unique_ptr<linux_os::SpiBus>>(const std::string& path,
                                                          std::uint32_t speed_hz)>
      open_spi;
  std::function<Result<std::unique_ptr<linux_os::I2cBus>>(const std::string& path)> open_i2c;
  /// The ADS1115s opened so far, by I2C device and address: two axes' pots, and motor current
  /// and temperature inputs, wired to one chip share it and take turns with its conversions.
  std::map<std::pair<std::string, std::uint8_t>, std::shared_ptr<linux_os::Ads1115Chip>>
      ads1115_chips;

  /// spidev and i2c-dev.
  static HardwarePorts linux_devices(linux_os::GpioProvider* gpio,
                                     std::chrono::steady_clock::time_point epoch);
};

/// Opens the drive of `axis`; throws UsageError naming the key of what cannot be had (nothing is
/// left energized then).
std::unique_ptr<ports::AxisDrive> open_axis_drive(const HardwareAxisConfig& axis,
                                                  const PwmConfig& pwm, HardwarePorts& ports);
/// Opens the ADC of an `mcp3008` / `ads1115` sensor; throws UsageError naming the key. A second
/// axis on an ADS1115 already open shares it (on another channel).
std::unique_ptr<ports::AxisSensor> open_adc_sensor(const HardwareAxisConfig& axis,
                                                   HardwarePorts& ports);

/// The pulse sensor's lines and home switch of a `pulses` sensor, on GPIO edge events; throws
/// UsageError naming the key.
std::unique_ptr<ports::PulseInput> open_pulse_input(const HardwareAxisConfig& axis,
                                                    HardwarePorts& ports);

/// The brake's release line of `axis`; nullptr without `brake`. Throws UsageError naming the key.
std::unique_ptr<ports::BrakeLine> open_brake_line(const HardwareAxisConfig& axis,
                                                  HardwarePorts& ports);
/// The current, temperature and driver-fault inputs of `axis`; nullptr without any. Throws
/// UsageError naming the key.
std::unique_ptr<ports::MotorSensor> open_motor_sensor(const HardwareAxisConfig& axis,
                                                      HardwarePorts& ports);

}  // namespace azt::app
