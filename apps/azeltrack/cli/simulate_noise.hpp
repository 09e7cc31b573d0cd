#pragma once
// `azeltrack simulate --scenario sun-noise | moon-noise | drift` (docs/calibration.md): the
// noise measurement and the drift scan of the core on the simulated station and receiver, each
// printed beside the simulation's own truth.

#include <string>

#include "cli/simulate_calibration.hpp"
#include "config/sim_config.hpp"

namespace azt::app {

/// A cross scan to find `source`, then its noise measurement: the Y-factor found, the truth of
/// the simulated receiver (its model's rise with the beam on the source over cold sky) and the
/// value expected from the source's flux and the dish. Returns the exit status.
int run_noise_scenario(const SimConfig& config, const CalibrationScenario& scenario,
                       const std::string& source);

/// A drift scan of --source (default the Sun): the beamwidth found and the simulated one, the
/// offset along the source's path found and true. Returns the exit status.
int run_drift_scenario(const SimConfig& config, const CalibrationScenario& scenario);

}  // namespace azt::app
