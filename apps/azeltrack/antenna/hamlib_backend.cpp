// The `hamlib` backend: an existing rotator controller (GS-232, SPID, EasyComm boxes, or another
// rotctld) closes its own loop. To the one station backend it is a setpoint drive on each axis
// and a position report for each axis's sensor (azt/linux/hamlib_rotator_ports.hpp), supervised
// like any other drive.
#include <algorithm>

#include "antenna/antenna_backend.hpp"
#include "antenna/station_backend.hpp"
#include "azt/control/station_setup.hpp"
#include "azt/linux/hamlib_rotator_ports.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

/// The box's position comes every poll_s at best, over a bus: a report is stale only after five
/// polls (and never sooner than a second). The box's own deadband is the window.
control::StationControlConfig control_config(const DaemonConfig& config) {
  control::StationControlConfig c = config.station.control_config();
  const double stale_s = std::max(1.0, 5.0 * config.hamlib.poll_s);
  for (control::SupervisorConfig* s : {&c.az_supervisor, &c.el_supervisor}) {
    s->stale_s = std::max(s->stale_s, stale_s);
  }
  for (control::AxisDriveConfig* d : {&c.az_drive, &c.el_drive}) {
    d->kind = control::DriveKind::Setpoint;
  }
  return c;
}

}  // namespace

std::unique_ptr<AntennaBackend> make_hamlib_backend(const DaemonConfig& config) {
  auto rotator = linux_os::HamlibRotator::open(config.hamlib);
  if (!rotator) throw UsageError("[hamlib]: " + rotator.error().message);
  const std::string describe =
      "Hamlib rotator model " + std::to_string(config.hamlib.model) +
      (config.hamlib.device.empty() ? std::string() : " on " + config.hamlib.device);
  return make_station_backend(
      control_config(config), config.station.believed_start(), config.station.corrections,
      linux_os::make_hamlib_rotator_ports(std::move(rotator).value(), describe,
                                          config.station.el_fixed_deg),
      describe);
}

}  // namespace azt::app
