// The satellite schedule in the console (docs/web-api.md, docs/satellites.md "The schedule"):
// its plan, the list edited whole, and the hand-back after an operator took the antenna.
#include <toml++/toml.h>

#include <cctype>

#include "console/daemon_console.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

/// More than any station works; a bound on what one request can make the daemon plan.
constexpr std::size_t kMaxEntries = 32;

/// One entry of the body as a [[schedule]] table. Only the form is checked here: the file's
/// loader refuses what the schema refuses (a range, a repeated satellite) and names it.
toml::table schedule_item(const json& e, std::size_t i) {
  const std::string field = "entries[" + std::to_string(i) + "]";
  if (!e.is_object()) throw ApiError(400, field, field + " must be an object");
  toml::table t;
  for (const auto& [key, value] : e.items()) {
    if (key == "sat" && value.is_string() && !value.get<std::string>().empty() &&
        value.get<std::string>().size() <= 64) {
      t.insert_or_assign("sat", value.get<std::string>());
    } else if (key == "min_el_deg" && value.is_number()) {
      t.insert_or_assign("min_el_deg", value.get<double>());
    } else if (key == "preempt" && value.is_string()) {
      t.insert_or_assign("preempt", value.get<std::string>());
    } else {
      std::string where = field;
      where.append(".").append(key);
      throw ApiError(400, where, where + ": not a valid schedule key");
    }
  }
  if (!t.contains("sat")) throw ApiError(400, field + ".sat", field + ": `sat` is required");
  return t;
}

toml::array schedule_items(const json& body) {
  const auto it = body.find("entries");
  if (it == body.end() || !it->is_array()) {
    throw ApiError(400, "entries", "`entries` must be a list of {sat, min_el_deg, preempt}");
  }
  if (it->size() > kMaxEntries) {
    throw ApiError(400, "entries", "at most " + std::to_string(kMaxEntries) + " satellites");
  }
  toml::array items;
  for (std::size_t i = 0; i < it->size(); ++i) items.push_back(schedule_item((*it)[i], i));
  return items;
}

/// The file's refusal names the table ("[schedule#2].sat …"): the console marks the row, so the
/// field is said as the body's ("entries[1].sat").
ApiError entry_refusal(const ApiError& e) {
  const std::string message = e.what();
  const auto at = message.find("[schedule#");
  if (at == std::string::npos) return e;
  std::size_t end = at + 10;
  while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end])) != 0) {
    ++end;
  }
  if (end == at + 10 || message.compare(end, 2, "].") != 0 || end - at - 10 > 3) return e;
  std::size_t key_end = end + 2;
  while (key_end < message.size() &&
         (std::islower(static_cast<unsigned char>(message[key_end])) != 0 ||
          message[key_end] == '_')) {
    ++key_end;
  }
  const std::size_t item = std::stoul(message.substr(at + 10, end - at - 10));
  if (item == 0) return e;
  return ApiError(
      e.status(),
      "entries[" + std::to_string(item - 1) + "]." + message.substr(end + 2, key_end - end - 2),
      message);
}

}  // namespace

json DaemonConsole::schedule() {
  if (p_.schedule == nullptr) throw ApiError(404, "", "no satellite schedule here");
  return p_.schedule->plan_view();
}

void DaemonConsole::act_schedule(const std::string& action, const json& body,
                                 const std::string& source, ActDone done) {
  if (p_.schedule == nullptr) throw ApiError(404, "", "no satellite schedule here");
  if (action == "schedule/resume") {
    if (!p_.schedule->resume(source)) throw ApiError(409, "", "no [[schedule]]: nothing to resume");
    done(ActResult{{{"schedule", p_.schedule->state()}}, std::nullopt});
    return;
  }
  toml::array items = schedule_items(body);  // a refusal here changes nothing
  p_.log(source + ": schedule of " + std::to_string(items.size()) + " satellites saved");
  save(
      "entries",
      [items = std::move(items)](toml::table& root) {
        if (items.empty()) {
          root.erase("schedule");
        } else {
          root.insert_or_assign("schedule", items);
        }
      },
      [this] {
        apply_live(LiveApply::Schedule);
        // The plan is made again off the loop: the answer has the list, GET the plan after.
        return json{{"schedule", p_.schedule->plan_view()}};
      },
      [done = std::move(done)](ActResult result) {
        if (result.error) result.error = entry_refusal(*result.error);
        done(std::move(result));
      });
}

}  // namespace azt::app
