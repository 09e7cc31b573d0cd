#pragma once
// The station controller over its ports: each tick reads both axes'
// sensors, hands the controller a reading when both have a new one, and applies its duties to
// both drives. A station with a polarisation axis (StationControlConfig::pol, its drive and its
// sensor, or its pulse input when its drive counts pulses) drives it beside them, read and
// supervised alone: its own demand each tick, its own faults; an E-stop, a drive's write error
// and shutdown stop it with the others. The daemon's one station backend and the virtual-time
// simulations both run it, so a simulated hour exercises exactly the code a station runs; what
// differs is the ports (the plants read by the hub model or by the hub firmware, the Linux
// devices, a Hamlib box).

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/control/corrections.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/ports/station_ports.hpp"

namespace azt::control {

class PortedStation {
 public:
  /// `start_mount` is where the axes are believed to be before the first reading.
  PortedStation(const StationControlConfig& control, AzEl start_mount,
                const PositionCorrections& corrections, ports::StationPorts ports);
  ~PortedStation();
  PortedStation(const PortedStation&) = delete;
  PortedStation& operator=(const PortedStation&) = delete;
  PortedStation(PortedStation&&) = delete;
  PortedStation& operator=(PortedStation&&) = delete;

  /// One control tick: read, decide, drive. A latched sensor fault stops every drive instead.
  /// `pol` is the polarisation axis's wish (ignored without one; nullopt feed: it holds).
  void tick(double now_s, const Demand& demand, const AzEl& rate, const PolDemand& pol = {});
  void set_limits(double now_s, const LimitSwitches& limits);
  /// The polarisation axis's travel-end switches (no pol axis: nothing to do).
  void set_pol_limits(double now_s, const LimitPair& limits);
  /// Both drives off now, the station latched with `reason` until the faults are cleared.
  void stop_with(double now_s, std::string_view reason);
  /// The operator's command to home a pulse-counted axis (0 az, 1 el, 2 pol); why not.
  std::optional<std::string> home(double now_s, std::size_t axis);
  /// Ends every homing in progress (the operator's STOP), the pol axis's too; the axes stay
  /// unreferenced.
  void stop_homing(double now_s, std::string_view reason);

  /// One line per fault: latched axis faults, a drive's write error, each sensor's error (a
  /// link two axes share is named once).
  [[nodiscard]] std::vector<std::string> faults() const;
  void clear_faults();
  void set_corrections(const PositionCorrections& corrections) {
    station_.set_corrections(corrections);
  }

  /// The controller: its axes, position and the duties it last gave the drives.
  [[nodiscard]] const StationController& station() const { return station_; }
  /// The polarisation axis; nullptr when the station has none.
  [[nodiscard]] const PolAxis* pol() const { return pol_ ? &*pol_ : nullptr; }

 private:
  [[nodiscard]] std::optional<std::string> latched_sensor() const;
  void read_sensors(double now_s);
  /// Pulse-counted axes: homing at start when configured, this tick's edges, and the axis marked
  /// fresh (its count is read every tick) so the other axis's reading goes in. The pol axis's
  /// count too, read alone as its sensor is.
  void read_pulses(double now_s);
  /// Axis `i`'s (0 az, 1 el, 2 pol) pulse input and the PulseAxis it feeds; nullptr when either
  /// is missing (the axis has another sensor, or no such axis).
  [[nodiscard]] ports::PulseInput* pulse_input(std::size_t i) const;
  [[nodiscard]] const PulseAxis* pulse_axis(std::size_t i) const;
  void read_pol(double now_s);
  void apply(double now_s, const Duties& d);
  /// Reads each axis's motor sensor, if it has one, and hands the readings to its axis.
  void read_motors(double now_s);
  /// Writes each brake line as its axis's brake wants it; false after a write error (stopped).
  bool apply_brakes(double now_s);
  /// The sensors that hold a fault of their own: both axes', and the pol axis's if it has one
  /// (a pulse-counted pol axis has none).
  [[nodiscard]] std::vector<const ports::AxisSensor*> sensors() const;

  ports::StationPorts ports_;
  StationController station_;
  std::optional<PolAxis> pol_;
  std::optional<std::string> pol_sensor_fault_;
  std::array<ports::SensorReading, 2> fresh_;
  std::array<std::optional<std::string>, 2> sensor_fault_;
  std::string drive_fault_;
  /// A motor sensor's read error per axis (az, el, pol): the axis trips on it, this says why.
  std::array<std::optional<std::string>, 3> motor_sensor_fault_;
  /// The pol axis is read by its pulse count (ports' pol_pulse_input), not by pol_sensor.
  bool pol_counted_ = false;
  /// The first tick has begun each pulse axis's homing (az, el, pol).
  std::array<bool, 3> pulses_started_{};
};

}  // namespace azt::control
