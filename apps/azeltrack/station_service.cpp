#include "station_service.hpp"

#include <cmath>

#include "azt/control/axis_geometry.hpp"
#include "azt/util/format_number.hpp"

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
  auto here = antenna_.position(now_());
  // The client gets an error (never a cached angle); the operator sees why (issue 12 §7).
  if (!here && log_)
    log_("a PC program: position asked for while unknown (no fresh sensor reading)");
  return here;
}

ServiceStatus StationService::refuse(std::string_view client, ServiceStatus status,
                                     const std::string& why) {
  if (log_) log_(std::string(client) + ": refused: " + why);
  return status;
}

void StationService::announce(std::string_view client, const std::string& what) {
  // One line per change of owner or kind of command, not one per Gpredict update.
  std::string line = std::string(client) + ": " + what;
  if (line != last_announced_ && log_) log_(line);
  last_announced_ = std::move(line);
}

ServiceStatus StationService::goto_position(std::string_view client, double az_deg, double el_deg) {
  if (!std::isfinite(az_deg) || !std::isfinite(el_deg) || !limits_.accepts_az(az_deg) ||
      !limits_.accepts_el(el_deg)) {
    return refuse(client, ServiceStatus::Invalid,
                  "target az " + format_number(az_deg) + "° el " + format_number(el_deg) +
                      "° is outside what this rotator accepts");
  }
  if (!control::plan_elevation(el_deg, el_range_)) {
    return refuse(client, ServiceStatus::Invalid,
                  "target el " + format_number(el_deg) + "° is outside the elevation travel (" +
                      format_number(el_range_.min_deg) + "° to " +
                      format_number(el_range_.max_deg) + "°)");
  }
  if (faulted()) return refuse(client, ServiceStatus::Rejected, "a fault is latched");
  auto r = modes_.external(control::AzEl{control::wrap_360(az_deg), el_deg}, std::string(client));
  if (!r) {
    return refuse(client,
                  modes_.external_locked() ? ServiceStatus::Rejected : ServiceStatus::Invalid,
                  r.error().message);
  }
  announce(client, "EXT position target");
  return ServiceStatus::Ok;
}

ServiceStatus StationService::goto_axis(std::string_view client, proto::Axis axis, double deg) {
  // The other axis keeps the present EXT target, or stays where the antenna is.
  std::optional<control::AzEl> base;
  if (modes_.mode() == control::Mode::External) base = modes_.fixed_target();
  if (!base) {
    const auto here = antenna_.position(now_());
    if (!here)
      return refuse(client, ServiceStatus::Unavailable,
                    "one-axis move while the position is unknown");
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
  if (faulted()) return refuse(client, ServiceStatus::Rejected, "move: a fault is latched");
  auto r = modes_.external_jog(control::Jog{motion.az, motion.el}, std::string(client), now_());
  if (!r) {
    return refuse(client,
                  modes_.external_locked() ? ServiceStatus::Rejected : ServiceStatus::Invalid,
                  "move: " + r.error().message);
  }
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
  if (faulted()) return refuse(client, ServiceStatus::Rejected, "park: a fault is latched");
  if (modes_.external_locked()) {
    return refuse(client, ServiceStatus::Rejected, "park: PC programs are locked out");
  }
  auto r = modes_.park(1);
  if (!r) return refuse(client, ServiceStatus::Invalid, "park: " + r.error().message);
  announce(client, "PARK");
  return ServiceStatus::Ok;
}

void StationService::activity(std::string_view client) { modes_.heard_from(client, now_()); }

}  // namespace azt::app
