#pragma once
// The Linux drives behind the core's AxisDrive port (docs/hardware.md): an IBT-2 bridge on
// sysfs PWM (its enables on GPIO lines when wired), relays on GPIO lines (forward/reverse, or
// seed 002's power + polarity pair), and seed 001's MCP41010 in a rotator box that closes its own
// loop. Each is off when destroyed.

#include <memory>
#include <optional>
#include <string>

#include "azt/control/relay_drive.hpp"
#include "azt/control/setpoint_drive.hpp"
#include "azt/linux/gpio.hpp"
#include "azt/linux/pwm_hbridge.hpp"
#include "azt/linux/spi_device.hpp"
#include "azt/ports/axis_drive.hpp"

namespace azt::linux_os {

/// The enables (null when wired high) go high with the first drive and low on off(), so a stop
/// or a fault also cuts the bridge in hardware.
std::unique_ptr<ports::AxisDrive> make_pwm_bridge_drive(PwmHBridge bridge,
                                                        std::unique_ptr<GpioOutput> enable,
                                                        std::string what);

/// Forward/reverse lines, or with `power_polarity` set the power line first and the polarity
/// line second. The station's RelayDrive already keeps the minimum on-time and the reversal
/// dead time; this only switches, the releasing line always first.
std::unique_ptr<ports::AxisDrive> make_relay_lines_drive(
    std::unique_ptr<GpioOutput> first, std::unique_ptr<GpioOutput> second,
    std::optional<control::PowerPolarityConfig> power_polarity, std::string what);

/// Codes are written only when they change, and again after a write failed (the pot may have
/// lost power and woken at mid-scale).
std::unique_ptr<ports::AxisDrive> make_mcp41010_drive(std::unique_ptr<SpiBus> bus,
                                                      const control::SetpointCalibration& wiper,
                                                      std::string what);

}  // namespace azt::linux_os
