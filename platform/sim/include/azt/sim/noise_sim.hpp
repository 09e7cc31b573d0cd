#pragma once
// Noise measurements and drift scans in simulation (docs/calibration.md): the daemon's station on
// the simulated plants (sky_bench.hpp) runs the core's sessions, calibration::NoiseMeasurement
// and calibration::DriftScan, against the simulated receiver, as `azeltrack simulate --scenario
// sun-noise | moon-noise | drift` prints them.

#include <optional>
#include <string>
#include <vector>

#include "azt/calibration/drift_scan.hpp"
#include "azt/calibration/noise_measurement.hpp"
#include "azt/calibration/scan_fit.hpp"
#include "azt/sim/calibration_sim.hpp"

namespace azt::sim {

struct NoiseSimResult {
  std::optional<calibration::ScanFit> peak;  ///< the cross scan that found the source first
  std::string peak_refused;                  ///< why it found nothing (measured on the ephemeris)
  std::optional<calibration::NoiseResult> noise;
  std::string refused;  ///< why no Y-factor, when none
  control::AzEl sky;    ///< the source as the measurement began
  std::vector<std::string> faults;
  double simulated_s = 0.0;
};

/// A cross scan of `source` to put the beam on it (as an operator peaks the Sun first), then the
/// noise measurement of `plan` about the peak it found; a fresh station at t = 0.
NoiseSimResult simulate_noise_measurement(const CalibrationSimSetup& setup,
                                          const CalibrationSource& source,
                                          calibration::NoisePlan plan);

struct DriftSimResult {
  std::optional<calibration::DriftFit> fit;
  std::string refused;
  double rate_deg_s = 0.0;  ///< the source's rate across the sky at the start (the ephemeris)
  double transit_s = 0.0;
  control::AzEl held;  ///< the point held: the source's place at the transit
  std::vector<std::string> faults;
  double simulated_s = 0.0;
};

/// A drift scan of `source` (`spec`: beamwidth, lead, bins) on a fresh station at t = 0.
DriftSimResult simulate_drift_scan(const CalibrationSimSetup& setup,
                                   const CalibrationSource& source,
                                   const calibration::DriftSpec& spec);

}  // namespace azt::sim
