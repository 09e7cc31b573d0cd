#pragma once
// One axis's hardware for the `hardware` backend: what moves it (an IBT-2 bridge on sysfs PWM,
// relays on GPIO lines, or an MCP41010 in a rotator box) and what reads it (a potentiometer on
// an MCP3008 or ADS1115; the EncoderHub is read by the backend itself, for both axes at once).
// Devices are opened through HardwarePorts, so tests put simulated devices behind them.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "azt/linux/gpio.hpp"
#include "azt/linux/i2c_device.hpp"
#include "azt/linux/spi_device.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {

class Ads1115Chip;  // axis_io.cpp

struct HardwarePorts {
  linux_os::GpioProvider* gpio = nullptr;  ///< needed by relay drives
  std::function<Result<std::unique_ptr<linux_os::SpiBus>>(const std::string& path,
                                                          std::uint32_t speed_hz)>
      open_spi;
  std::function<Result<std::unique_ptr<linux_os::I2cBus>>(const std::string& path)> open_i2c;
  /// The ADS1115s opened so far, by I2C device and address: two axes wired to one chip share it
  /// and take turns with its conversions.
  std::map<std::pair<std::string, std::uint8_t>, std::shared_ptr<Ads1115Chip>> ads1115_chips;

  /// spidev and i2c-dev.
  static HardwarePorts linux_devices(linux_os::GpioProvider* gpio);
};

class AxisActuator {
 public:
  AxisActuator() = default;
  AxisActuator(const AxisActuator&) = delete;
  AxisActuator& operator=(const AxisActuator&) = delete;
  virtual ~AxisActuator() = default;
  /// What the station wants until the next tick: a duty (relays: its sign), or for a rotator box
  /// the setpoint in mount degrees. A write error is returned; the drive is then off.
  virtual Result<bool> apply(double now_s, double duty, std::optional<double> setpoint_deg) = 0;
  /// Everything off now, best effort (shutdown, faults).
  virtual void off(double now_s) = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

/// What a sensor has at a tick: a new angle in degrees of the calibration, or nullopt when it has
/// nothing new yet (an ADC conversion still running). The backend takes nothing new as it takes
/// a hub between frames: no fault, the last reading ages and goes stale if nothing follows.
using SensorReading = std::optional<double>;

class AxisSensor {
 public:
  AxisSensor() = default;
  AxisSensor(const AxisSensor&) = delete;
  AxisSensor& operator=(const AxisSensor&) = delete;
  virtual ~AxisSensor() = default;
  /// Called once a control tick, at `now_s` on the loop's clock; never waits for a device. An
  /// error for a bus failure, a conversion that never finishes or a broken wire (never a
  /// plausible angle made of a bad sample).
  virtual Result<SensorReading> read(double now_s) = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

/// Opens the drive of `axis`; throws UsageError naming the key of what cannot be had (nothing is
/// left energized then).
std::unique_ptr<AxisActuator> make_actuator(const HardwareAxisConfig& axis, const PwmConfig& pwm,
                                            HardwarePorts& ports);
/// Opens the ADC of an `mcp3008` / `ads1115` sensor; throws UsageError naming the key. A second
/// axis on an ADS1115 already open shares it (on another channel).
std::unique_ptr<AxisSensor> make_adc_sensor(const HardwareAxisConfig& axis, HardwarePorts& ports);

}  // namespace azt::app
