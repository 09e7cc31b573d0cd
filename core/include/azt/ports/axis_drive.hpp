#pragma once
// What moves one axis, as the station controller sees it: an H-bridge, a pair of
// relays, a rotator box given a setpoint, or the simulated plant's motor. The simulation and the
// Linux and Hamlib adapters implement it; the station backend drives the one StationController's
// duties through it ("the simulator is a HAL": one controller, whatever is behind the port).

#include <optional>
#include <string>

#include "azt/util/result.hpp"

namespace azt::ports {

class AxisDrive {
 public:
  AxisDrive() = default;
  AxisDrive(const AxisDrive&) = delete;
  AxisDrive& operator=(const AxisDrive&) = delete;
  AxisDrive(AxisDrive&&) = delete;
  AxisDrive& operator=(AxisDrive&&) = delete;
  virtual ~AxisDrive() = default;

  /// What the station wants until the next tick, at `now_s` on the control loop's clock: a duty
  /// in −1…1 (relays take its sign), or for a rotator box the setpoint in mount degrees. A write
  /// error is returned; the drive is then off.
  virtual Result<bool> apply(double now_s, double duty, std::optional<double> setpoint_deg) = 0;
  /// Everything off now, best effort (shutdown, faults): never fails, never waits.
  virtual void off(double now_s) = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace azt::ports
