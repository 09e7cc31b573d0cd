#include "azt/control/ported_station.hpp"

#include <algorithm>
#include <utility>

namespace azt::control {
namespace {

constexpr std::array<const char*, 2> kAxisNames{"az", "el"};

}  // namespace

PortedStation::PortedStation(const StationControlConfig& control, AzEl start_mount,
                             const PositionCorrections& corrections, ports::StationPorts ports)
    : ports_(std::move(ports)), station_(control, start_mount) {
  station_.set_corrections(corrections);
}

PortedStation::~PortedStation() { stop_with(0.0, "stopped by the daemon"); }

void PortedStation::tick(double now_s, const Demand& demand, const AzEl& rate) {
  if (const auto held = latched_sensor()) {
    // Never drive on angles read at the wrong resolution: stopped, and saying why.
    stop_with(now_s, "held by the sensor fault (" + *held + ")");
    return;
  }
  read_sensors(now_s);
  // Both axes' readings go in together, stamped with the older: if either sensor falls silent
  // the station sees a stale position and stops the drives.
  if (fresh_[0] && fresh_[1]) {
    station_.on_encoder_reading(std::min(fresh_[0]->at_s, fresh_[1]->at_s), fresh_[0]->deg,
                                fresh_[1]->deg);
    fresh_ = {};
  }
  apply(now_s, station_.tick(now_s, demand, rate));
}

void PortedStation::set_limits(double now_s, const LimitSwitches& limits) {
  apply(now_s, station_.set_limits(limits));
}

void PortedStation::stop_with(double now_s, std::string_view reason) {
  station_.emergency_stop(now_s, reason);
  const Duties d = station_.duties();
  const std::array<std::optional<double>, 2> setpoint{d.az_setpoint_deg, d.el_setpoint_deg};
  for (std::size_t i = 0; i < 2; ++i) {
    (void)ports_.drives.at(i)->apply(now_s, 0.0, setpoint.at(i));
    ports_.drives.at(i)->off(now_s);
  }
}

std::vector<std::string> PortedStation::faults() const {
  std::vector<std::string> out;
  for (const auto& [name, axis] : {std::pair{"az", station_.az()}, {"el", station_.el()}}) {
    if (axis.fault != FaultKind::None) {
      out.push_back(std::string(name) + ": " + std::string(to_string(axis.fault)) + ": " +
                    axis.reason);
    }
  }
  if (!drive_fault_.empty()) out.push_back(drive_fault_);
  for (std::size_t i = 0; i < 2; ++i) {
    for (const auto& f : {ports_.sensors.at(i)->latched_fault(), sensor_fault_.at(i)}) {
      // Two axes on one link (a hub) report its loss once.
      if (f && std::find(out.begin(), out.end(), *f) == out.end()) out.push_back(*f);
    }
  }
  return out;
}

void PortedStation::clear_faults() {
  station_.clear_faults();
  drive_fault_.clear();
  for (const auto& sensor : ports_.sensors) sensor->clear_fault();
}

std::optional<std::string> PortedStation::latched_sensor() const {
  for (const auto& sensor : ports_.sensors) {
    if (auto fault = sensor->latched_fault()) return fault;
  }
  return std::nullopt;
}

void PortedStation::read_sensors(double now_s) {
  for (std::size_t i = 0; i < 2; ++i) {
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

void PortedStation::apply(double now_s, const Duties& d) {
  const std::array<double, 2> duty{d.az, d.el};
  const std::array<std::optional<double>, 2> setpoint{d.az_setpoint_deg, d.el_setpoint_deg};
  for (std::size_t i = 0; i < 2; ++i) {
    if (auto r = ports_.drives.at(i)->apply(now_s, duty.at(i), setpoint.at(i)); !r) {
      drive_fault_ = std::string(kAxisNames.at(i)) + " drive: " + r.error().message;
      stop_with(now_s, "stopped by the daemon");
      return;
    }
  }
}

}  // namespace azt::control
