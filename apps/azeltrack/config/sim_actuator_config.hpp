#pragma once
// The simulated actuator dish: an elevation whose sensor measures the length of a linear actuator
// ([hardware.el] sensor = "pulses" with counts_per_mm, or a pot on an ADC with
// pot_calibration_mm; the actuator's triangle either way), flown by the `sim` backend and
// `azeltrack simulate` as a linear actuator (platform/sim's ActuatorDishPlant), the station
// reading it by its count or its pot as on the real dish (docs/hardware.md, "Linear actuators").

#include <optional>

#include "azt/sim/plant_setup.hpp"

namespace azt::app {

class ConfigFile;

/// The actuator elevation the file describes, if [hardware.el] counts a reed's pulses per
/// millimetre of an actuator, or reads the actuator's length with a pot (nullopt otherwise: a
/// count in degrees, a quadrature pair or a pot in degrees is not simulated as an actuator);
/// `el` is the elevation plant ([sim.el] start_deg: where the dish starts). [hardware.el] is
/// read by the daemon's own reader, every key checked. Throws UsageError naming the key
/// ([sim.el] drop_pulse_at_s with a pot: there is no reed to lose a pulse of).
std::optional<sim::SimActuatorElevation> sim_actuator_from(const ConfigFile& file,
                                                           const sim::AxisParams& el);

}  // namespace azt::app
