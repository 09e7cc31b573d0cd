#pragma once
// An axis's brake line and motor readings on the Pi's own devices, behind the core's ports
// (azt/ports/motor_io.hpp; docs/hardware.md "Brake, current and temperature"): the brake's
// release relay on a GPIO output, the IBT-2's current sense and a temperature sensor on an
// MCP3008's or an ADS1115's channels, the driver's fault line on a GPIO input.

#include <memory>
#include <optional>
#include <string>

#include "azt/control/motor_trips.hpp"
#include "azt/linux/gpio.hpp"
#include "azt/linux/pot_sensors.hpp"
#include "azt/linux/spi_device.hpp"
#include "azt/ports/motor_io.hpp"

namespace azt::linux_os {

/// The brake's line: set each tick as the axis's brake wants it, off (brake applied) when the
/// station stops and when the line is destroyed.
std::unique_ptr<ports::BrakeLine> make_gpio_brake_line(std::unique_ptr<GpioOutput> line);

struct MotorAdcInputs {
  double vref_v =
      3.3;  ///< the MCP3008's VREF: a code of 1023 is vref·1023/1024 (not the ADS1115's)
  std::optional<unsigned> current_channel;
  control::CurrentSense current;
  std::optional<unsigned> temperature_channel;
  double temperature_c_per_v = 100.0;
  double temperature_offset_c = 0.0;
};

/// The readings of one axis's motor: one SPI transfer a tick per ADC channel (as a pot on an
/// MCP3008: about 24 µs each at 1 MHz, no wait), and the driver's fault line as its last edge
/// left it. `bus` may be null when no channel is given; `fault` may be null.
std::unique_ptr<ports::MotorSensor> make_motor_sensor(std::unique_ptr<SpiBus> bus,
                                                      const MotorAdcInputs& inputs,
                                                      std::unique_ptr<GpioInput> fault,
                                                      std::string what);

/// The same readings on `chip`'s channels (added by the caller as slow channels: one turn after
/// each round of a pot's conversions on the chip, Ads1115Chip), at ±4.096 V. No read waits: a
/// channel has a new reading only on the tick that fetches its conversion, every other tick
/// alone on the chip with a pot (every fourth for each of two channels), and the last one stands
/// between (motor_trips.hpp). `fault` may be null.
std::unique_ptr<ports::MotorSensor> make_ads1115_motor_sensor(std::shared_ptr<Ads1115Chip> chip,
                                                              const MotorAdcInputs& inputs,
                                                              std::unique_ptr<GpioInput> fault,
                                                              std::string what);

}  // namespace azt::linux_os
