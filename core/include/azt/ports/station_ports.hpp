#pragma once
// The axes' drives and sensors: what a station backend is handed by the simulation, the Linux
// devices or a Hamlib rotator box.

#include <array>
#include <memory>

#include "azt/ports/axis_drive.hpp"
#include "azt/ports/axis_sensor.hpp"
#include "azt/ports/motor_io.hpp"
#include "azt/ports/pulse_input.hpp"

namespace azt::ports {

/// Azimuth first, then elevation; the polarisation axis's, if the station has one (nullptr: no
/// pol axis). A station with a fixed elevation (StationControlConfig::el_fixed_deg) has no
/// elevation drive or sensor: both are nullptr.
/// Brakes and motor sensors are optional per axis (nullptr: none).
struct StationPorts {
  std::array<std::unique_ptr<AxisDrive>, 2> drives;
  std::array<std::unique_ptr<AxisSensor>, 2> sensors;
  std::unique_ptr<AxisDrive> pol_drive;
  std::unique_ptr<AxisSensor> pol_sensor;
  std::array<std::unique_ptr<BrakeLine>, 2> brakes;
  std::array<std::unique_ptr<MotorSensor>, 2> motor_sensors;
  std::unique_ptr<BrakeLine> pol_brake;
  std::unique_ptr<MotorSensor> pol_motor_sensor;
  /// A pulse-counted axis's lines (its AxisDriveConfig::pulses), azimuth then elevation; such an
  /// axis has no sensor. nullptr: none.
  std::array<std::unique_ptr<PulseInput>, 2> pulse_inputs;
  /// The pol axis's, when its PolAxisConfig::drive counts pulses: read in place of pol_sensor.
  std::unique_ptr<PulseInput> pol_pulse_input;
};

}  // namespace azt::ports
