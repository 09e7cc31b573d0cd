#pragma once
// The simulated actuator dish: a pulse-counted elevation ([hardware.el] sensor = "pulses" with
// counts_per_mm and the actuator's triangle) flown by the `sim` backend and `azeltrack simulate`
// as a linear actuator with a reed and a home switch (platform/sim's ActuatorDishPlant), the
// station reading it by its count as on the real dish (docs/hardware.md, "Linear actuators").

#include <optional>

#include "azt/sim/plant_setup.hpp"

namespace azt::app {

class ConfigFile;

/// The actuator elevation the file describes, if [hardware.el] counts a reed's pulses per
/// millimetre of an actuator (nullopt otherwise: a count in degrees or a quadrature pair is not
/// simulated); `el` is the elevation plant ([sim.el] start_deg: where the dish starts). Throws
/// UsageError naming the key.
std::optional<sim::SimActuatorElevation> sim_actuator_from(const ConfigFile& file,
                                                           const sim::AxisParams& el);

}  // namespace azt::app
