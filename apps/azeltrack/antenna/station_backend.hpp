#pragma once
// The one station backend: the StationController, reading each axis through its
// sensor port and moving it through its drive port. The simulated antenna, the Linux devices and
// a Hamlib rotator box differ only in the ports they hand it, so what the simulation measures is
// what the station runs.

#include <memory>
#include <string>

#include "antenna/antenna_backend.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/ports/station_ports.hpp"

namespace azt::app {

/// `start_mount` is where the axes are believed to be before the first reading; `describe` is
/// what the daemon announces ("simulated antenna (14/14-bit encoders)").
std::unique_ptr<AntennaBackend> make_station_backend(
    const control::StationControlConfig& control, control::AzEl start_mount,
    const control::PositionCorrections& corrections, ports::StationPorts ports,
    std::string describe);

}  // namespace azt::app
