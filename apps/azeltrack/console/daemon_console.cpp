// The console's actions (DaemonConsole::act): motion and scans through the station's front door,
// the configuration actions dispatched to console_settings.cpp.
#include "console/daemon_console.hpp"

#include <map>

#include "azt/calibration/scan_plan.hpp"
#include "console/body_fields.hpp"
#include "console/scan_timing_body.hpp"

namespace azt::app {

using json = nlohmann::json;

void DaemonConsole::act(const std::string& action, const json& body, const std::string& source,
                        ActDone done) {
  if (action == "target") {
    done(ActResult{act_target(body, source), std::nullopt});
    return;
  }
  if (action == "stop") {
    p_.commands.stop(CommandSource{CommandSource::Kind::Console, source});
    done(ActResult{});
    return;
  }
  if (action == "control/pc") {
    const auto outcome = p_.commands.allow_pc(CommandSource{CommandSource::Kind::Console, source});
    done(ActResult{{{"mode", outcome.mode}, {"control", control_json()}}, std::nullopt});
    return;
  }
  if (action == "scan") {
    done(ActResult{act_scan(body, source), std::nullopt});
    return;
  }
  if (action == "scan/stop") {
    if (p_.scanner != nullptr) p_.scanner->stop("stopped by " + source);
    done(ActResult{p_.scanner != nullptr ? p_.scanner->to_json() : json{{"state", "idle"}},
                   std::nullopt});
    return;
  }
  if (action.rfind("calibration/", 0) == 0 || action.rfind("noise", 0) == 0 ||
      action.rfind("recording", 0) == 0) {
    act_measurement(action, body, source, std::move(done));
    return;
  }
  if (action == "restart") {
    if (!p_.restart) throw ApiError(409, "", "this daemon cannot restart itself");
    p_.log(source + ": restart asked: the motors stop, the daemon starts again");
    p_.restart(source);
    done(ActResult{{{"restarting", true}}, std::nullopt});
    return;
  }
  if (action == "hardware/direction-test" || action == "hardware/home") {
    act_hardware(action, body, source, std::move(done));
    return;
  }
  if (action == "satellites/refresh") {
    act_satellites_refresh(source, done);
    return;
  }
  if (action == "schedule" || action == "schedule/resume") {
    act_schedule(action, body, source, std::move(done));
    return;
  }
  if (action == "pol") {
    act_pol(body, source, std::move(done));
    return;
  }
  if (action == "faults/clear") {
    p_.antenna.clear_faults();
    p_.log(source + ": latched faults cleared");
    done(ActResult{});
    return;
  }
  using Act = void (DaemonConsole::*)(const json&, ActDone);
  static const std::map<std::string, Act, std::less<>> save_actions = {
      {"correction", &DaemonConsole::act_correction},
      {"config/band", &DaemonConsole::act_band},
      {"config/dx", &DaemonConsole::act_dx},
      {"config/offsets", &DaemonConsole::act_offsets},
      {"scan/apply", &DaemonConsole::act_scan_apply},
      {"config/tilt", &DaemonConsole::act_tilt},
      {"config/park", &DaemonConsole::act_park},
      {"time/servers", &DaemonConsole::act_time_servers}};
  const auto it = save_actions.find(action);
  if (it != save_actions.end()) {
    (this->*(it->second))(body, std::move(done));
    return;
  }
  if (action.rfind("config/", 0) == 0) {
    act_settings(action.substr(7), body, std::move(done));
    return;
  }
  throw ApiError(404, "", "no such action: " + action);
}

void DaemonConsole::act_satellites_refresh(const std::string& source, const ActDone& done) {
  if (p_.elements == nullptr) throw ApiError(404, "", "no element feed here");
  if (!p_.elements->refresh_now(p_.unix_s())) {
    throw ApiError(409, "", "the sources are being fetched: try again when that is done");
  }
  p_.log(source + ": element sources fetched now");
  done(ActResult{});
}

void DaemonConsole::act_hardware(const std::string& action, const json& body,
                                 const std::string& source, ActDone done) {
  if (action == "hardware/home") {
    act_home(body, source, done);
  } else {
    act_direction_test(body, source, std::move(done));
  }
}

void DaemonConsole::act_direction_test(const json& body, const std::string& source, ActDone done) {
  if (p_.direction_test == nullptr) throw ApiError(404, "", "no direction test here");
  const std::string axis = body_text(body, "axis");
  auto finished = [done = std::move(done)](json result, std::optional<std::string> error) {
    if (error) {
      done(ActResult{{}, ApiError(409, "", *error)});
    } else {
      done(ActResult{std::move(result), std::nullopt});
    }
  };
  if (auto refused = p_.direction_test->start(axis, source, std::move(finished))) {
    // An axis the station has is "not now"; anything else is a bad value of `axis`.
    const bool known = axis == "az" || axis == "el" || axis == "pol";
    throw ApiError(known ? 409 : 400, known ? "" : "axis", *refused);
  }
  p_.log(source + ": direction test of the " + axis + " axis");
}

void DaemonConsole::upload_elements(std::string text, const std::string& source, ActDone done) {
  if (p_.elements == nullptr) throw ApiError(404, "", "no element feed here");
  p_.log(source + ": uploads element sets (" + std::to_string(text.size()) + " bytes)");
  p_.elements->upload(std::move(text), p_.unix_s(), [done = std::move(done)](Result<json> outcome) {
    if (!outcome) {
      done(ActResult{{}, ApiError(400, "", outcome.error().message)});
      return;
    }
    done(ActResult{std::move(outcome).value(), std::nullopt});
  });
}

TargetRequest DaemonConsole::target_request(const json& body) {
  if (body.contains("name")) return target_from_name(body_text(body, "name"));
  if (body.contains("ra_deg") || body.contains("dec_deg")) {
    return RaDecTarget{body_number(body, "ra_deg"), body_number(body, "dec_deg")};
  }
  if (body.contains("park")) {
    return ParkTarget{body_whole_number(body, "park", 1, 4, "park must be a slot number 1 to 4")};
  }
  if (body.contains("az_deg") || body.contains("el_deg")) {
    return PositionTarget{body_number(body, "az_deg"), body_number(body, "el_deg")};
  }
  throw ApiError(400, "name", "expected name, ra_deg/dec_deg, park or az_deg/el_deg");
}

/// The scan's settings from the request, checked before anything moves (the plan's own
/// refusals name their field first: "beamwidth_deg must be …").
std::pair<calibration::ScanSpec, calibration::ScanTiming> scan_settings(const json& body) {
  calibration::ScanSpec spec;
  if (body.contains("kind")) {
    auto kind = calibration::parse_scan_kind(body_text(body, "kind"));
    if (!kind) throw ApiError(400, "kind", kind.error().message);
    spec.kind = *kind;
  }
  spec.beamwidth_deg = body_number(body, "beamwidth_deg");
  if (body.contains("points_per_line")) {
    spec.points_per_line = static_cast<std::size_t>(body_whole_number(
        body, "points_per_line", 5, 101, "points_per_line must be odd, 5 to 101"));
  }
  spec.half_span_beams =
      body_optional_number(body, "half_span_beams").value_or(spec.half_span_beams);
  spec.reference_beams =
      body_optional_number(body, "reference_beams").value_or(spec.reference_beams);
  const calibration::ScanTiming timing = scan_timing_from(body);
  if (auto plan = calibration::plan_scan(spec); !plan) {
    const std::string& why = plan.error().message;
    throw ApiError(400, why.substr(0, why.find(' ')), why);
  }
  return {spec, timing};
}

json DaemonConsole::act_scan(const json& body, const std::string& source) {
  if (p_.scanner == nullptr) throw ApiError(503, "", "no pointing scans here");
  const auto [spec, timing] = scan_settings(body);
  if (p_.calibration != nullptr && p_.calibration->running()) {
    throw ApiError(409, "", "a calibration session is running: stop it first");
  }
  const std::string name = body_text(body, "source");
  if (auto ready = p_.scanner->ready(p_.monotonic_s()); !ready) {
    throw ApiError(503, "", ready.error().message);
  }
  json pointed = act_target(json{{"name", name}}, source);  // tracks the source, or refuses
  if (!p_.sky.target()) throw ApiError(400, "source", "a scan needs a sky source");
  auto started = p_.scanner->start(p_.sky.target()->name, spec, timing, p_.monotonic_s());
  if (!started) throw ApiError(503, "", started.error().message);
  p_.log(source + ": pointing scan of " + p_.sky.target()->name);
  pointed["scan"] = p_.scanner->to_json();
  return pointed;
}

json DaemonConsole::act_target(const json& body, const std::string& source) {
  const CommandOutcome outcome =
      p_.commands.point(CommandSource{CommandSource::Kind::Console, source}, target_request(body));
  if (const auto& r = outcome.refusal) {
    // The same refusal a PC program gets, as HTTP: a bad value, "not now", or no position.
    const unsigned status = r->status == proto::ServiceStatus::Rejected      ? 409
                            : r->status == proto::ServiceStatus::Unavailable ? 503
                                                                             : 400;
    throw ApiError(status, r->field, r->reason);
  }
  return {{"mode", outcome.mode}, {"target", outcome.target}};
}

}  // namespace azt::app
