#pragma once
// `azeltrack simulate --scenario calibrate | scan` (docs/calibration.md): pointing calibration on
// the simulated mount, whose beam points wrong as [sim.mount_errors] says, read by the simulated
// receiver of [sim.receiver] (docs/calibration.md).

#include <string>

#include "config/sim_config.hpp"

namespace azt::app {

struct CalibrationScenario {
  std::string from;            ///< ISO 8601 UTC; empty: now
  double hours = 24.0;         ///< calibrate: the longest the scans may take, simulated
  std::string source;          ///< scan: the source to scan (sun, moon, a radio source)
  double sun_every_min = 0.0;  ///< calibrate: the Sun every this long while up (0: by coverage)
  bool json = false;
};

/// Runs the calibration session (the daemon's planner and scan log) on the simulated station,
/// fits the pointing model to its log and prints the recovered terms and the beam's error over
/// the sky before and after, with the encoders' quantisation floor. Returns the exit status.
int run_calibrate_scenario(const SimConfig& config, const CalibrationScenario& scenario);

/// One cross scan (with a raster first if it finds nothing) of one source: the offset found and
/// the offset the mount's errors put there.
int run_scan_scenario(const SimConfig& config, const CalibrationScenario& scenario);

}  // namespace azt::app
