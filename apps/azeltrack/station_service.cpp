#include "station_service.hpp"

#include <cmath>

#include "azt/control/axis_geometry.hpp"

namespace azt::app {

using proto::ServiceStatus;

StationService::StationService(control::ModeController& modes, AntennaBackend& antenna,
                               proto::TargetLimits limits, control::ElevationRange el_range,
                               std::string info, Clock now, Log log)
    : modes_(modes),
      antenna_(antenna),
      limits_(limits),
      el_range_(el_range),
      info_(std::move(info)),
      now_(std::move(now)),
      log_(std::move(log)) {}

std::optional<proto::PositionReport> StationService::position() const {
  return antenna_.position(now_());
}

void StationService::announce(std::string_view client, const std::string& what) {
  // One line per change of owner or kind of command, not one per Gpredict update.
  std::string line = std::string(client) + ": " + what;
  if (line != last_announced_ && log_) log_(line);
  last_announced_ = std::move(line);
}

ServiceStatus StationService::goto_position(std::string_view client, double az_deg, double el_deg) {
  if (!std::isfinite(az_deg) || !std::isfinite(el_deg) || !limits_.accepts_az(az_deg) ||
      !limits_.accepts_el(el_deg) || !control::plan_elevation(el_deg, el_range_)) {
    return ServiceStatus::Invalid;
  }
  if (faulted()) return ServiceStatus::Rejected;
  auto r = modes_.external(control::AzEl{control::wrap_360(az_deg), el_deg}, std::string(client));
  if (!r) return modes_.external_locked() ? ServiceStatus::Rejected : ServiceStatus::Invalid;
  announce(client, "EXT position target");
  return ServiceStatus::Ok;
}

ServiceStatus StationService::goto_axis(std::string_view client, proto::Axis axis, double deg) {
  // The other axis keeps the present EXT target, or stays where the antenna is.
  std::optional<control::AzEl> base;
  if (modes_.mode() == control::Mode::External) base = modes_.fixed_target();
  if (!base) {
    const auto here = position();
    if (!here) return ServiceStatus::Unavailable;
    base = control::AzEl{here->az_deg, here->el_deg};
  }
  if (axis == proto::Axis::Az) {
    base->az_deg = deg;
  } else {
    base->el_deg = deg;
  }
  return goto_position(client, base->az_deg, base->el_deg);
}

ServiceStatus StationService::move(std::string_view client, proto::AxisMotion motion) {
  if (faulted()) return ServiceStatus::Rejected;
  auto r = modes_.external_jog(control::Jog{motion.az, motion.el}, std::string(client), now_());
  if (!r) return modes_.external_locked() ? ServiceStatus::Rejected : ServiceStatus::Invalid;
  announce(client, "EXT continuous move (stops after 1 s without traffic)");
  return ServiceStatus::Ok;
}

void StationService::stop(std::string_view client, std::optional<proto::Axis> axis) {
  if (axis && modes_.mode() == control::Mode::External) {
    const auto demand = modes_.demand(std::nullopt);
    if (demand.jog) {
      control::Jog jog = *demand.jog;
      (*axis == proto::Axis::Az ? jog.az : jog.el) = 0;
      if (jog.az != 0 || jog.el != 0) {
        (void)modes_.external_jog(jog, std::string(client), now_());
        return;
      }
    } else if (const auto here = position()) {
      (void)goto_axis(client, *axis, *axis == proto::Axis::Az ? here->az_deg : here->el_deg);
      return;
    }
  }
  modes_.stop();
  announce(client, "STOP");
}

ServiceStatus StationService::park(std::string_view client) {
  if (modes_.external_locked() || faulted()) return ServiceStatus::Rejected;
  auto r = modes_.park(1);
  if (!r) return ServiceStatus::Invalid;
  announce(client, "PARK");
  return ServiceStatus::Ok;
}

void StationService::activity(std::string_view client) { modes_.heard_from(client, now_()); }

}  // namespace azt::app
