#pragma once
// The `actuator_*` keys of [hardware.az|el]: the triangle of a linear actuator turning the axis
// (core control/actuator_geometry.hpp, docs/hardware.md "Linear actuators"). Two sensors measure
// an actuator's length rather than its angle and need it: pulses counted per millimetre
// (`counts_per_mm`) and a feedback pot calibrated in millimetres (`pot_calibration_mm`).

#include <string_view>

#include "azt/control/actuator_geometry.hpp"

namespace azt::app {

class ConfigSection;

/// The triangle of `s`, every length and angle required because `needed_by` (the key that
/// measures length) is given. Throws UsageError naming the key.
control::ActuatorGeometryConfig read_actuator(const ConfigSection& s, std::string_view needed_by);

/// Refuses the triangle's keys on an axis whose sensor measures no length: wiring written there
/// would otherwise do nothing. (actuator_extend has a default and loads alone, as every key with
/// one does.)
void refuse_actuator_keys(const ConfigSection& s);

}  // namespace azt::app
