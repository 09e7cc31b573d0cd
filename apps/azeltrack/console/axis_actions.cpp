// The motor axes' own hardware in the console (docs/hardware.md; docs/web-api.md): /api/state
// `antenna.axes`, what the station's controller knows of each brake, motor and pulse count, and
// POST /api/hardware/home, the operator's command to home a pulse-counted axis. Homing moves the
// axis open loop towards its switch, as at start-up: the axis's own checks refuse it while a
// fault is latched (the E-stop among them), and any STOP ends it (StationCommands::stop).
#include "console/body_fields.hpp"
#include "console/daemon_console.hpp"

namespace azt::app {

using json = nlohmann::json;

namespace {

/// What one axis has beyond a motor and a sensor; empty when it has nothing more.
json axis_hardware_json(const control::AxisStatus& s) {
  json out = json::object();
  if (s.brake) {
    out["brake"] = std::string(control::to_string(*s.brake));
    out["brake_released"] = s.brake_release;
  }
  if (s.current_a) out["current_a"] = *s.current_a;
  if (s.temperature_c) out["temperature_c"] = *s.temperature_c;
  if (!s.reset_refused.empty()) out["reset_refused"] = s.reset_refused;
  if (s.homing) {
    out["homing"] = std::string(control::to_string(*s.homing));
    out["held"] = s.held.empty() ? json(nullptr) : json(s.held);
  }
  if (s.pulse_count) out["pulse_count"] = *s.pulse_count;
  return out;
}

}  // namespace

json DaemonConsole::axes_json() const {
  json out = json::object();
  for (const NamedAxisStatus& a : p_.antenna.axes()) {
    json hardware = axis_hardware_json(a.status);
    if (!hardware.empty()) out[a.axis] = std::move(hardware);
  }
  return out;
}

void DaemonConsole::act_home(const json& body, const std::string& source, const ActDone& done) {
  const std::string axis = body_text(body, "axis");
  // An axis the station has without a pulse count (or not at all) is the station's refusal, 409.
  if (axis != "az" && axis != "el" && axis != "pol") {
    throw ApiError(400, "axis", "axis must be \"az\", \"el\" or \"pol\" (a pulse-counted axis)");
  }
  if (auto refused = p_.antenna.home(p_.monotonic_s(), axis)) throw ApiError(409, "", *refused);
  p_.log(source + ": homing of the " + axis + " axis");
  done(ActResult{{{"axis", axis}, {"axes", axes_json()}}, std::nullopt});
}

}  // namespace azt::app
