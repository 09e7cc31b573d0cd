#include "station/station_service.hpp"

namespace azt::app {

using proto::ServiceStatus;

StationService::StationService(StationCommands& commands, const control::ModeController& modes,
                               AntennaBackend& antenna, std::function<double()> now,
                               std::string info, Log log)
    : commands_(commands),
      modes_(modes),
      antenna_(antenna),
      now_(std::move(now)),
      info_(std::move(info)),
      log_(std::move(log)) {}

std::optional<proto::PositionReport> StationService::position() const {
  auto here = antenna_.position(now_());
  // The client gets an error (never a cached angle); the operator sees why.
  if (!here && log_)
    log_("a PC program: position asked for while unknown (no fresh sensor reading)");
  return here;
}

void StationService::refused(std::string_view client, std::string_view why) {
  commands_.report_refusal(program(client), Refusal{ServiceStatus::Invalid, "", std::string(why)});
}

ServiceStatus StationService::goto_position(std::string_view client, double az_deg, double el_deg) {
  return status_of(commands_.point(program(client), PositionTarget{az_deg, el_deg}));
}

ServiceStatus StationService::goto_axis(std::string_view client, proto::Axis axis, double deg) {
  // The other axis keeps the present EXT target, or stays where the antenna is.
  std::optional<control::AzEl> base;
  if (modes_.mode() == control::Mode::External) base = modes_.fixed_target();
  if (!base) {
    const auto here = antenna_.position(now_());
    if (!here) {
      commands_.report_refusal(program(client), Refusal{ServiceStatus::Unavailable, "",
                                                        "one-axis move while the position is "
                                                        "unknown"});
      return ServiceStatus::Unavailable;
    }
    base = control::AzEl{here->az_deg, here->el_deg};
  }
  (axis == proto::Axis::Az ? base->az_deg : base->el_deg) = deg;
  return goto_position(client, base->az_deg, base->el_deg);
}

ServiceStatus StationService::move(std::string_view client, proto::AxisMotion motion) {
  return status_of(commands_.jog(program(client), control::Jog{motion.az, motion.el}));
}

void StationService::stop(std::string_view client, std::optional<proto::Axis> axis) {
  if (axis && modes_.mode() == control::Mode::External) {
    const auto demand = modes_.demand(std::nullopt);
    if (demand.jog) {
      control::Jog jog = *demand.jog;
      (*axis == proto::Axis::Az ? jog.az : jog.el) = 0;
      if (jog.az != 0 || jog.el != 0) {
        (void)commands_.jog(program(client), jog);
        return;
      }
    } else if (const auto here = position()) {
      // Holding the stopped axis where it is; if even that is refused, everything stops.
      const double deg = *axis == proto::Axis::Az ? here->az_deg : here->el_deg;
      if (goto_axis(client, *axis, deg) == ServiceStatus::Ok) return;
    }
  }
  commands_.stop(program(client));
}

ServiceStatus StationService::park(std::string_view client) {
  return status_of(commands_.point(program(client), ParkTarget{1}));
}

void StationService::activity(std::string_view client) { commands_.heard_from(program(client)); }

}  // namespace azt::app
