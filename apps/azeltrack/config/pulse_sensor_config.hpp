#pragma once
// sensor = "pulses" on [hardware.az|el|pol]: a reed, Hall or quadrature sensor counted on
// GPIO lines, the home switch it is referenced to, what a count measures (degrees, or millimetres
// of a linear actuator through its triangle) and how the axis homes (docs/hardware.md, "Pulse
// sensors and homing"). The core's PulseAxis runs it; the `hardware` backend opens the lines.

#include <string>

#include "config/hardware_config.hpp"

namespace azt::app {

class ConfigSection;

/// Reads the pulse keys of `s` into `a` (sensor = "pulses"); refuses them on any other sensor.
/// Throws UsageError naming the key.
void read_pulse_sensor(const ConfigSection& s, HardwareAxisConfig& a, const std::string& chip);

}  // namespace azt::app
