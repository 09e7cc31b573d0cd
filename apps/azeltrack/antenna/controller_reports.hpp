#pragma once
// What the backends built on the StationController (sim, pwm) report, in one place.

#include <optional>
#include <string>
#include <vector>

#include "azt/control/station_controller.hpp"
#include "azt/proto/rotator_service.hpp"

namespace azt::app {

/// The sky position with the mount angle and motion, or nullopt while a reading is stale or an
/// axis is faulted (no cached angle is ever reported).
inline std::optional<proto::PositionReport> station_position(
    const control::StationController& station, double now_s) {
  const auto sky = station.sky_position(now_s);
  if (!sky) return std::nullopt;
  const auto az = station.az();
  const auto el = station.el();
  return proto::PositionReport{sky->az_deg, sky->el_deg, az.mount_deg, az.moving || el.moving,
                               station.faulted()};
}

/// "az: stall: driven for 2 s …", one line per latched axis fault.
inline std::vector<std::string> station_faults(const control::StationController& station) {
  std::vector<std::string> out;
  for (const auto& [name, axis] : {std::pair{"az", station.az()}, {"el", station.el()}}) {
    if (axis.fault != control::FaultKind::None) {
      out.push_back(std::string(name) + ": " + std::string(control::to_string(axis.fault)) + ": " +
                    axis.reason);
    }
  }
  return out;
}

}  // namespace azt::app
