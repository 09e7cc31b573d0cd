#pragma once
// The daemon's station on the simulated plants with the simulated receiver, stepped together in
// virtual time (docs/calibration.md "In simulation"): what the noise and drift simulations
// (noise_sim.hpp) run their sessions on. The receiver hears the sources through the plants'
// true beam (their shafts through [sim.mount_errors]); the station knows the beam only through
// its encoders and its corrections.

#include <optional>
#include <string>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "azt/sim/calibration_sim.hpp"
#include "azt/sim/radio_receiver.hpp"
#include "azt/sim/station_loop.hpp"

namespace azt::sim {

class SkyBench {
 public:
  explicit SkyBench(const CalibrationSimSetup& setup);

  [[nodiscard]] double now() const { return t_; }

  /// One control tick towards the fixed `demand` (drives still once there).
  void hold(const control::AzEl& demand);
  /// One control tick following `source` + `offset` (the ephemeris read now and a second ahead
  /// for the rate); a source that cannot be placed holds.
  void follow(const CalibrationSource& source, const calibration::SkyOffset& offset);

  /// The controller drives an axis.
  [[nodiscard]] bool driving() const;
  [[nodiscard]] std::optional<control::AzEl> encoders() const;
  /// Where the station believes the beam points relative to `source` now (its corrected
  /// reading); nullopt when either is unknown.
  [[nodiscard]] std::optional<calibration::SkyOffset> pointed(
      const CalibrationSource& source) const;
  /// Where `source` is now relative to where the station believes the beam points, in the plane
  /// tangent to the sky at the beam (drift_scan.hpp).
  [[nodiscard]] std::optional<calibration::SkyOffset> source_from_beam(
      const CalibrationSource& source) const;
  /// The receiver's reading when one is due (its rate_hz), else nullopt.
  std::optional<double> reading();

  /// Where the beam really points: the plants' shafts through the mount's errors.
  [[nodiscard]] control::AzEl true_beam() const;
  /// Every source's emitter at `t_s`.
  [[nodiscard]] std::vector<RadioEmitter> sky_at(double t_s) const;
  [[nodiscard]] const SimulatedReceiver& receiver() const { return receiver_; }
  [[nodiscard]] const std::vector<std::string>& faults() const { return faults_; }

 private:
  void step(const std::optional<control::AzEl>& demand, const control::AzEl& rate);

  const CalibrationSimSetup& setup_;
  StationLoop loop_;
  SimulatedReceiver receiver_;
  std::vector<std::string> faults_;
  double t_ = 0.0;
  double next_reading_s_ = 0.0;
};

}  // namespace azt::sim
