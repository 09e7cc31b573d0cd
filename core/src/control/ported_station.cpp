#include "azt/control/ported_station.hpp"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace azt::control {
namespace {

void add_axis_fault(std::vector<std::string>& out, const char* name, const AxisStatus& axis) {
  if (axis.fault == FaultKind::None) return;
  // A motor trip's words name their axis already ("az: motor temperature …").
  const std::string prefix = std::string(name) + ": ";
  std::string_view reason = axis.reason;
  if (reason.starts_with(prefix)) reason.remove_prefix(prefix.size());
  out.push_back(prefix + std::string(to_string(axis.fault)) + ": " + std::string(reason));
  if (!axis.reset_refused.empty()) out.push_back(axis.reset_refused);
}

const char* axis_name(std::size_t i) {
  constexpr std::array<const char*, 3> kNames{"az", "el", "pol"};
  return kNames.at(i);
}

/// A motor sensor's sample as the axis's protection takes it; a read error is a reading that is
/// not a number (the axis trips on it rather than running unwatched).
MotorReadings motor_readings(const Result<ports::MotorSample>& r) {
  if (!r) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    return MotorReadings{kNaN, kNaN, std::nullopt};
  }
  return MotorReadings{r.value().current_a, r.value().temperature_c, r.value().driver_fault};
}

void add_once(std::vector<std::string>& out, const std::optional<std::string>& fault) {
  // Two axes on one link (a hub) report its loss once.
  if (fault && std::find(out.begin(), out.end(), *fault) == out.end()) out.push_back(*fault);
}

}  // namespace

PortedStation::PortedStation(const StationControlConfig& control, AzEl start_mount,
                             const PositionCorrections& corrections, ports::StationPorts ports)
    : ports_(std::move(ports)), station_(control, start_mount) {
  station_.set_corrections(corrections);
  // A pol axis needs its settings, its drive and what reads it (its pulse input when its drive
  // counts pulses, else its sensor); with any of them missing there is none.
  if (control.pol && ports_.pol_drive) {
    const bool counted = control.pol->drive.pulses.has_value();
    if (counted ? ports_.pol_pulse_input != nullptr : ports_.pol_sensor != nullptr) {
      pol_.emplace(*control.pol, control.tick_s);
      pol_counted_ = counted;
    }
  }
}

PortedStation::~PortedStation() { stop_with(0.0, "stopped by the daemon"); }

void PortedStation::tick(double now_s, const Demand& demand, const AzEl& rate,
                         const PolDemand& pol) {
  if (const auto held = latched_sensor()) {
    // Never drive on angles read at the wrong resolution: stopped, and saying why.
    stop_with(now_s, "held by the sensor fault (" + *held + ")");
    return;
  }
  read_sensors(now_s);
  read_pulses(now_s);
  // Both axes' readings go in together, stamped with the older: if either sensor falls silent
  // the station sees a stale position and stops the drives. A fixed elevation has no sensor.
  if (fresh_[0] && station_.el_fixed()) {
    station_.on_encoder_reading(fresh_[0]->at_s, fresh_[0]->deg, 0.0);
    fresh_ = {};
  } else if (fresh_[0] && fresh_[1]) {
    station_.on_encoder_reading(std::min(fresh_[0]->at_s, fresh_[1]->at_s), fresh_[0]->deg,
                                fresh_[1]->deg);
    fresh_ = {};
  }
  if (pol_ && !pol_counted_) read_pol(now_s);
  read_motors(now_s);
  if (pol_) pol_->drive(now_s, pol);
  apply(now_s, station_.tick(now_s, demand, rate));
}

void PortedStation::set_limits(double now_s, const LimitSwitches& limits) {
  apply(now_s, station_.set_limits(limits));
}

void PortedStation::set_pol_limits(double now_s, const LimitPair& limits) {
  if (!pol_) return;
  pol_->axis().set_limits(limits);
  apply(now_s, station_.duties());
}

void PortedStation::stop_with(double now_s, std::string_view reason) {
  station_.emergency_stop(now_s, reason);
  const Duties d = station_.duties();
  const std::array<std::optional<double>, 2> setpoint{d.az_setpoint_deg, d.el_setpoint_deg};
  for (std::size_t i = 0; i < 2; ++i) {
    if (!ports_.drives.at(i)) continue;  // a fixed elevation has no drive
    (void)ports_.drives.at(i)->apply(now_s, 0.0, setpoint.at(i));
    ports_.drives.at(i)->off(now_s);
  }
  if (pol_) {
    pol_->axis().emergency_stop(now_s, reason);
    (void)ports_.pol_drive->apply(now_s, 0.0, pol_->axis().setpoint_deg());
    ports_.pol_drive->off(now_s);
  }
  // The brakes after the motors: a spring brake holds whatever the controller does next.
  for (const auto& brake : ports_.brakes) {
    if (brake) brake->off(now_s);
  }
  if (ports_.pol_brake) ports_.pol_brake->off(now_s);
}

std::vector<std::string> PortedStation::faults() const {
  std::vector<std::string> out;
  add_axis_fault(out, "az", station_.az());
  add_axis_fault(out, "el", station_.el());
  if (pol_) add_axis_fault(out, "pol", pol_->axis().status());
  if (!drive_fault_.empty()) out.push_back(drive_fault_);
  for (const auto& fault : motor_sensor_fault_) add_once(out, fault);
  for (std::size_t i = 0; i < 2; ++i) {
    if (ports_.sensors.at(i)) add_once(out, ports_.sensors.at(i)->latched_fault());
    add_once(out, sensor_fault_.at(i));
  }
  if (pol_ && !pol_counted_) {
    add_once(out, ports_.pol_sensor->latched_fault());
    add_once(out, pol_sensor_fault_);
  }
  return out;
}

void PortedStation::clear_faults() {
  station_.clear_faults();
  if (pol_) pol_->axis().clear_faults();
  drive_fault_.clear();
  for (const auto& sensor : ports_.sensors) {
    if (sensor) sensor->clear_fault();
  }
  if (pol_ && !pol_counted_) ports_.pol_sensor->clear_fault();
}

std::vector<const ports::AxisSensor*> PortedStation::sensors() const {
  std::vector<const ports::AxisSensor*> out;
  for (const auto& sensor : ports_.sensors) {
    if (sensor) out.push_back(sensor.get());
  }
  if (pol_ && !pol_counted_) out.push_back(ports_.pol_sensor.get());
  return out;
}

std::optional<std::string> PortedStation::latched_sensor() const {
  for (const auto* sensor : sensors()) {
    if (auto fault = sensor->latched_fault()) return fault;
  }
  return std::nullopt;
}

void PortedStation::read_sensors(double now_s) {
  for (std::size_t i = 0; i < 2; ++i) {
    if (!ports_.sensors.at(i)) continue;  // a fixed elevation has no sensor
    auto r = ports_.sensors.at(i)->read(now_s);
    if (!r) {
      sensor_fault_.at(i) = r.error().message;  // no reading: the station goes stale
    } else if (r.value()) {
      fresh_.at(i) = r.value();
      sensor_fault_.at(i).reset();
    }
    // Otherwise nothing new yet (an ADC conversion running, a hub between frames).
  }
}

void PortedStation::read_pulses(double now_s) {
  for (std::size_t i = 0; i < pulses_started_.size(); ++i) {
    ports::PulseInput* input = pulse_input(i);
    const PulseAxis* pulses = pulse_axis(i);
    if (!input || !pulses) continue;
    if (!pulses_started_.at(i)) {
      pulses_started_.at(i) = true;
      if (pulses->home_at_start()) (void)home(now_s, i);
    }
    const std::vector<ports::PulseEdge> edges = input->take_edges();
    if (i == 2) {
      // The pol axis is read alone (no part of the sky position): its count is its reading.
      pol_->axis().on_pulse_edges(now_s, edges);
      continue;
    }
    station_.on_pulse_edges(now_s, i, edges);
    const double mount_deg = i == 0 ? station_.az().mount_deg : station_.el().mount_deg;
    fresh_.at(i) = ports::AxisSample{mount_deg, now_s};
  }
}

ports::PulseInput* PortedStation::pulse_input(std::size_t i) const {
  if (i < ports_.pulse_inputs.size()) return ports_.pulse_inputs.at(i).get();
  return i == 2 && pol_counted_ ? ports_.pol_pulse_input.get() : nullptr;
}

const PulseAxis* PortedStation::pulse_axis(std::size_t i) const {
  if (i < 2) return station_.pulses(i);
  return i == 2 && pol_ ? pol_->axis().pulses() : nullptr;
}

std::optional<std::string> PortedStation::home(double now_s, std::size_t axis) {
  ports::PulseInput* input = pulse_input(axis);
  if (!input || !pulse_axis(axis)) return std::string{"this axis has no pulse sensor to home"};
  if (axis == 2) return pol_->axis().home(now_s, input->home_closed());
  return station_.home(now_s, axis, input->home_closed());
}

void PortedStation::stop_homing(double now_s, std::string_view reason) {
  station_.stop_homing(now_s, reason);
  if (pol_) pol_->axis().stop_homing(now_s, reason);
}

void PortedStation::read_pol(double now_s) {
  auto r = ports_.pol_sensor->read(now_s);
  if (!r) {
    pol_sensor_fault_ = r.error().message;  // the pol axis goes stale and stops
  } else if (r.value()) {
    pol_->on_reading(r.value()->at_s, r.value()->deg);
    pol_sensor_fault_.reset();
  }
}

void PortedStation::apply(double now_s, const Duties& d) {
  const std::array<double, 2> duty{d.az, d.el};
  const std::array<std::optional<double>, 2> setpoint{d.az_setpoint_deg, d.el_setpoint_deg};
  for (std::size_t i = 0; i < 2; ++i) {
    if (!ports_.drives.at(i)) continue;
    if (auto r = ports_.drives.at(i)->apply(now_s, duty.at(i), setpoint.at(i)); !r) {
      drive_fault_ = std::string(axis_name(i)) + " drive: " + r.error().message;
      stop_with(now_s, "stopped by the daemon");
      return;
    }
  }
  if (pol_) {
    const DrivenAxis& axis = pol_->axis();
    if (auto r = ports_.pol_drive->apply(now_s, axis.duty(), axis.setpoint_deg()); !r) {
      drive_fault_ = "pol drive: " + r.error().message;
      stop_with(now_s, "stopped by the daemon");
      return;
    }
  }
  (void)apply_brakes(now_s);
}

bool PortedStation::apply_brakes(double now_s) {
  // Only an axis with a brake writes its line: the brake's own state says when it is released.
  const std::array<AxisStatus, 2> axes{station_.az(), station_.el()};
  std::array<std::pair<ports::BrakeLine*, std::optional<bool>>, 3> lines{
      std::pair{ports_.brakes[0].get(), std::optional<bool>{}},
      std::pair{ports_.brakes[1].get(), std::optional<bool>{}},
      std::pair{ports_.pol_brake.get(), std::optional<bool>{}}};
  for (std::size_t i = 0; i < 2; ++i) {
    if (axes.at(i).brake) lines.at(i).second = axes.at(i).brake_release;
  }
  if (pol_) {
    const AxisStatus pol = pol_->axis().status();
    if (pol.brake) lines[2].second = pol.brake_release;
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    auto [line, release] = lines.at(i);
    if (line == nullptr || !release) continue;
    if (auto r = line->apply(now_s, *release); !r) {
      drive_fault_ = std::string(axis_name(i)) + " brake: " + r.error().message;
      stop_with(now_s, "stopped by the daemon");
      return false;
    }
  }
  return true;
}

void PortedStation::read_motors(double now_s) {
  std::array<MotorReadings, 3> readings{};
  const std::array<ports::MotorSensor*, 3> motors{
      ports_.motor_sensors[0].get(), ports_.motor_sensors[1].get(), ports_.pol_motor_sensor.get()};
  for (std::size_t i = 0; i < motors.size(); ++i) {
    if (motors.at(i) == nullptr) continue;
    const auto r = motors.at(i)->read(now_s);
    readings.at(i) = motor_readings(r);
    if (r) {
      motor_sensor_fault_.at(i).reset();
    } else {
      motor_sensor_fault_.at(i) = std::string(axis_name(i)) + " motor sensor: " + r.error().message;
    }
  }
  // Every tick, readings or not: an over-current is timed on the loop's clock.
  station_.on_motor_readings(now_s, readings[0], readings[1]);
  if (pol_) pol_->axis().on_motor_readings(now_s, readings[2]);
}

}  // namespace azt::control
