// The polarisation axis in the console (docs/eme.md, "Polarisation axis"; docs/web-api.md): its
// state, and POST /api/pol choosing the mode and the angle. A choice passes the station's front
// door first (refused while a fault or the E-stop is latched, as a move is), is saved as [pol]
// like any setting (the manual angle excepted: it is the operator's of the moment), and reaches
// the follower through the same live path as PUT /api/config/pol.
#include <array>
#include <cmath>
#include <cstdio>

#include "console/body_fields.hpp"
#include "console/daemon_console.hpp"

namespace azt::app {

using json = nlohmann::json;

namespace {

json optional_deg(std::optional<double> deg) { return deg ? json(*deg) : json(nullptr); }

/// The faults of the pol axis among the station's: its supervisor's, its drive's, its sensor's.
json pol_faults(const std::vector<std::string>& faults) {
  json out = json::array();
  for (const auto& f : faults) {
    if (f.rfind("pol", 0) == 0) out.push_back(f);
  }
  return out;
}

/// `angle_deg` when given: a feed angle, −180 to 180 (a linear polarisation repeats every 180°;
/// more is a mistake, not a turn).
std::optional<double> body_angle(const json& body) {
  const auto angle = body_optional_number(body, "angle_deg");
  if (angle && std::fabs(*angle) > 180.0) {
    throw ApiError(400, "angle_deg", "angle_deg must be −180 to 180° (a feed angle from level)");
  }
  return angle;
}

/// Whether a mode takes the body's angle_deg: the fixed angle, or the operator's manual one.
bool takes_angle(control::PolMode mode) {
  switch (mode) {
    case control::PolMode::Fixed:
    case control::PolMode::Manual:
      return true;
    case control::PolMode::Off:
    case control::PolMode::Self:
    case control::PolMode::Dx:
    case control::PolMode::Split:
      return false;
  }
  return false;
}

/// [pol] in the file as re-read; a [pol] that is not a table is refused (nothing saved).
toml::table& pol_table(toml::table& root) {
  if (!root.contains("pol")) root.insert("pol", toml::table{});
  toml::table* t = root["pol"].as_table();
  if (t == nullptr) throw ApiError(400, "mode", "[pol] is not a table");
  return *t;
}

/// "pol manual 30.00°": the log's words for a choice.
std::string pol_words(control::PolMode mode, std::optional<double> angle) {
  std::string out = "pol " + std::string(control::to_string(mode));
  if (angle) {
    std::array<char, 32> text{};
    (void)std::snprintf(text.data(), text.size(), " %.2f°", *angle);
    out += text.data();
  }
  return out;
}

}  // namespace

json DaemonConsole::pol_json() const {
  const auto status = p_.antenna.pol_status();
  if (p_.pol == nullptr || !status) return nullptr;
  const control::PolSettings& s = p_.pol->settings();
  return {{"mode", std::string(control::to_string(s.mode))},
          {"fixed_deg", s.fixed_deg},
          {"manual_deg", optional_deg(p_.pol->manual_deg())},
          {"feed_target_deg", optional_deg(p_.pol->feed_deg())},
          {"target_mount_deg", optional_deg(status->target_mount_deg)},
          {"mount_deg", status->mount_deg},
          {"moving", status->moving},
          {"dpol_deg", optional_deg(p_.pol->dpol_deg())},
          {"transmitting", p_.pol->transmitting()},
          {"hold_while_keyed", s.hold_while_keyed},
          {"min_deg", status->min_deg},
          {"max_deg", status->max_deg},
          {"faults", pol_faults(p_.antenna.faults())}};
}

void DaemonConsole::act_pol(const json& body, const std::string& source, ActDone done) {
  if (p_.pol == nullptr || !p_.antenna.pol_status()) {
    throw ApiError(404, "", "this station has no polarisation axis ([mount.pol])");
  }
  if (!body.is_object()) throw ApiError(400, "mode", "give {\"mode\": …, \"angle_deg\": …}");
  const auto mode = control::parse_pol_mode(body_text(body, "mode"));
  if (!mode) throw ApiError(400, "mode", mode.error().message);
  const auto angle = body_angle(body);
  if (angle && !takes_angle(*mode)) {
    throw ApiError(400, "angle_deg", "angle_deg is for the fixed and manual modes");
  }
  // Off only stops the axis: always taken, as STOP is. Anything else may move it.
  if (*mode != control::PolMode::Off) {
    if (auto refusal = p_.commands.check_pol(CommandSource{CommandSource::Kind::Console, source}))
      throw ApiError(409, refusal->field, refusal->reason);
  }
  const std::string words = pol_words(*mode, angle);
  save(
      "mode",
      [chosen = *mode, angle](toml::table& root) {
        toml::table& pol = pol_table(root);
        pol.insert_or_assign("mode", std::string(control::to_string(chosen)));
        if (angle && chosen == control::PolMode::Fixed) pol.insert_or_assign("fixed_deg", *angle);
      },
      [this, chosen = *mode, angle, words, source] {
        apply_live(LiveApply::Pol);
        if (chosen == control::PolMode::Manual && angle) p_.pol->set_manual_deg(angle);
        p_.log(source + ": " + words);
        return json{{"pol", pol_json()}};
      },
      std::move(done));
}

}  // namespace azt::app
