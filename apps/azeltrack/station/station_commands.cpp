#include "station/station_commands.hpp"

#include <cmath>
#include <cstdio>
#include <type_traits>

#include "azt/util/format_number.hpp"

namespace azt::app {
namespace {

using proto::ServiceStatus;

std::string degrees(double deg) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f°", deg);
  return text;
}

Refusal invalid(std::string field, std::string reason) {
  return Refusal{ServiceStatus::Invalid, std::move(field), std::move(reason)};
}

}  // namespace

StationCommands::StationCommands(StationCommandParts parts) : p_(std::move(parts)) {
  commander_signature_ = mode_signature();
}

std::string StationCommands::mode_signature() const {
  return std::string(control::to_string(p_.modes.mode())) + "|" + p_.modes.who();
}

std::string StationCommands::commander() const {
  if (mode_signature() == commander_signature_) return commander_;
  return p_.modes.who();  // changed by itself: "move stopped: … silent for 1 s"
}

bool StationCommands::tracking_satellite() const {
  return p_.modes.mode() == control::Mode::Track && p_.satellites != nullptr &&
         p_.satellites->following();
}

CommandOutcome StationCommands::refuse(const CommandSource& source, Refusal refusal) {
  report_refusal(source, refusal);
  return CommandOutcome{std::move(refusal), "", ""};
}

void StationCommands::report_refusal(const CommandSource& source, const Refusal& refusal) {
  if (p_.refused) p_.refused(source, refusal);
}

CommandRecord StationCommands::record_of(const TargetRequest& request) const {
  return std::visit(
      [this](const auto& r) -> CommandRecord {
        using T = std::decay_t<decltype(r)>;
        if constexpr (std::is_same_v<T, PositionTarget>) {
          return {"position az " + degrees(r.az_deg) + " el " + degrees(r.el_deg), "position"};
        } else if constexpr (std::is_same_v<T, RaDecTarget>) {
          return {"track RA " + degrees(r.ra_deg) + " Dec " + degrees(r.dec_deg), ""};
        } else if constexpr (std::is_same_v<T, ParkTarget>) {
          return {"park in slot " + std::to_string(r.slot), ""};
        } else {  // a name, found: the modes hold it as tracked
          return {"track " + p_.modes.who(), ""};
        }
      },
      request);
}

CommandOutcome StationCommands::accept(const CommandSource& source, const CommandRecord& record) {
  commander_ = source.name;
  commander_kind_ = source.kind;
  commander_since_unix_s_ = p_.unix_s ? p_.unix_s() : 0.0;
  commander_signature_ = mode_signature();
  if (p_.accepted) p_.accepted(source, record);
  return CommandOutcome{std::nullopt, std::string(control::to_string(p_.modes.mode())),
                        p_.modes.who()};
}

std::optional<Refusal> StationCommands::check_position(const PositionTarget& p) const {
  // The protocols' own parsers refuse with the same words (TargetLimits::why_not_az).
  if (auto why = p_.limits.why_not_az(p.az_deg); !why.empty()) return invalid("az_deg", why);
  if (auto why = p_.limits.why_not_el(p.el_deg); !why.empty()) return invalid("el_deg", why);
  if (!control::plan_elevation(p.el_deg, p_.el_range)) {
    return invalid("el_deg", "el " + format_number(p.el_deg) +
                                 "° is outside the elevation travel (" +
                                 format_number(p_.el_range.min_deg) + "° to " +
                                 format_number(p_.el_range.max_deg) + "°)");
  }
  return std::nullopt;
}

std::optional<Refusal> StationCommands::check_now(const CommandSource& source) const {
  const auto faults = p_.antenna.faults();
  if (!faults.empty()) {
    return Refusal{ServiceStatus::Rejected, "", "a fault is latched (" + faults.front() + ")"};
  }
  if (source.kind == CommandSource::Kind::Program && p_.modes.external_locked()) {
    return Refusal{ServiceStatus::Rejected, "",
                   "PC programs are locked out: STOP was pressed (" + p_.modes.who() + ")"};
  }
  return std::nullopt;
}

CommandOutcome StationCommands::point(const CommandSource& source, const TargetRequest& request) {
  // A value the station can never take is Invalid whatever the state; then "not now".
  if (const auto* p = std::get_if<PositionTarget>(&request)) {
    if (auto bad = check_position(*p)) return refuse(source, std::move(*bad));
  }
  if (const auto* park = std::get_if<ParkTarget>(&request)) {
    if (park->slot < 1 || park->slot > control::ModeController::kParkSlots) {
      return refuse(source, invalid("park", "park must be a slot number 1 to 4"));
    }
  }
  if (auto not_now = check_now(source)) return refuse(source, std::move(*not_now));
  if (auto failed = apply(source, request)) return refuse(source, std::move(*failed));
  return accept(source, record_of(request));
}

std::optional<Refusal> StationCommands::apply(const CommandSource& source,
                                              const TargetRequest& request) {
  if (const auto* t = std::get_if<SatelliteTarget>(&request)) return track_satellite(*t);
  std::optional<Refusal> bad;
  if (const auto* p = std::get_if<PositionTarget>(&request)) {
    bad = go_to(source, *p);
  } else if (const auto* k = std::get_if<ParkTarget>(&request)) {
    bad = park(*k);
  } else if (const auto* n = std::get_if<NamedTarget>(&request)) {
    bad = track_named(*n);
  } else {
    bad = track_radec(std::get<RaDecTarget>(request));
  }
  if (!bad) forget_satellite();
  return bad;
}

std::optional<Refusal> StationCommands::park(const ParkTarget& t) {
  auto r = p_.modes.park(static_cast<int>(t.slot));
  if (!r) return invalid("park", r.error().message);
  return std::nullopt;
}

void StationCommands::forget_satellite() {
  if (p_.satellites != nullptr) p_.satellites->stop();
}

std::optional<Refusal> StationCommands::track_named(const NamedTarget& t) {
  const auto target = p_.sky.find(t.name);
  if (!target) {
    return invalid("name", "'" + t.name + "' is not a target of this station (sun, moon, or a " +
                               "[sky] source)");
  }
  p_.sky.follow(*target);
  p_.modes.track(target->name);
  return std::nullopt;
}

std::optional<Refusal> StationCommands::track_radec(const RaDecTarget& t) {
  auto target = astro::Target::radec(t.ra_deg, t.dec_deg);
  if (!target) {
    const bool ra_bad = !(t.ra_deg >= 0.0 && t.ra_deg < 360.0);
    return invalid(ra_bad ? "ra_deg" : "dec_deg", target.error().message);
  }
  p_.sky.follow(*target);
  p_.modes.track(target->name);
  return std::nullopt;
}

std::optional<Refusal> StationCommands::track_satellite(const SatelliteTarget& t) {
  if (p_.satellites == nullptr) return invalid("name", "no satellite catalogue");
  const auto here = p_.antenna.position(p_.monotonic_s());
  auto r = p_.satellites->follow(t.name_or_norad, p_.unix_s(),
                                 here ? here->az_mount_deg : p_.fallback_mount_az_deg);
  if (!r) return invalid("name", r.error().message);
  p_.modes.track(satellite_display_name(r.value()));
  return std::nullopt;
}

std::optional<Refusal> StationCommands::go_to(const CommandSource& source,
                                              const PositionTarget& p) {
  // Clients count azimuth their own way (−180…180, 0…450); the planner picks the mount's side.
  const control::AzEl sky{control::wrap_360(p.az_deg), p.el_deg};
  auto r = source.kind == CommandSource::Kind::Console ? p_.modes.manual(sky)
                                                       : p_.modes.external(sky, source.name);
  if (!r) return invalid("az_deg", r.error().message);
  return std::nullopt;
}

namespace {
/// "az +1 el 0", with a speed below full as "az +1 at 40%".
std::string jog_words(const control::Jog& jog) {
  const auto axis = [](const char* name, int direction, double speed) {
    std::string w = std::string(name) + (direction > 0 ? " +1" : direction < 0 ? " -1" : " 0");
    if (direction != 0 && speed < 1.0) {
      w += " at " + std::to_string(static_cast<int>(std::lround(speed * 100.0))) + "%";
    }
    return w;
  };
  return axis("az", jog.az, jog.az_speed) + " " + axis("el", jog.el, jog.el_speed);
}
}  // namespace

CommandOutcome StationCommands::jog(const CommandSource& source, control::Jog jog) {
  if (auto not_now = check_now(source)) return refuse(source, std::move(*not_now));
  const double now_s = p_.monotonic_s();
  auto r = source.kind == CommandSource::Kind::Hands
               ? p_.modes.manual_jog(jog, source.name, now_s)
               : p_.modes.external_jog(jog, source.name, now_s);
  if (!r) return refuse(source, invalid("", "move: " + r.error().message));
  forget_satellite();
  return accept(source, {"continuous move " + jog_words(jog) + " (stops after 1 s without traffic)",
                         "continuous move"});
}

void StationCommands::stop(const CommandSource& source) {
  switch (source.kind) {
    case CommandSource::Kind::Console:
      p_.modes.stop(true);
      break;
    case CommandSource::Kind::Hands:
      p_.modes.local_stop(source.name);
      break;
    case CommandSource::Kind::Program:
    case CommandSource::Kind::Configuration:
    case CommandSource::Kind::Schedule:
      p_.modes.stop(false);
      break;
  }
  p_.antenna.stop_homing(p_.monotonic_s(), "stopped by " + source.name);
  (void)accept(source, {"STOP", ""});
}

void StationCommands::release(const CommandSource& source) { p_.modes.end_jog(source.name); }

void StationCommands::heard_from(const CommandSource& source) {
  p_.modes.heard_from(source.name, p_.monotonic_s());
}

CommandOutcome StationCommands::allow_pc(const CommandSource& source) {
  if (source.kind != CommandSource::Kind::Console) {
    return refuse(source, Refusal{ServiceStatus::Rejected, "", "only the console hands over"});
  }
  p_.modes.allow_external();
  forget_satellite();
  return accept(source, {"allow PC control (nothing moves until a program sends a position)", ""});
}

std::optional<Refusal> StationCommands::check_pol(const CommandSource& source) {
  auto not_now = check_now(source);
  if (not_now) report_refusal(source, *not_now);
  return not_now;
}

ControlHolder StationCommands::control() const {
  std::string holder;
  switch (commander_kind_) {
    case CommandSource::Kind::Console:
      holder = "console";
      break;
    case CommandSource::Kind::Program:
      holder = "pc";
      break;
    case CommandSource::Kind::Configuration:
      holder = "configuration";
      break;
    case CommandSource::Kind::Schedule:
      holder = "schedule";
      break;
    case CommandSource::Kind::Hands:
      holder = "hands";
      break;
  }
  return ControlHolder{holder, commander(), commander_since_unix_s_, !p_.modes.external_locked()};
}

}  // namespace azt::app
