// The calibration session through the console (docs/web-api.md, docs/calibration.md "In the
// daemon"): the sources a station can scan, the session started and stopped, the fit of the scan
// log shown, applied as [pointing] (saved atomically through the store, as a scan's apply saves
// [corrections]) and kept in the models' history, any earlier model restored, and the scan log
// exported and imported as CSV (parsed and appended on the worker, never on the loop).
#include <filesystem>
#include <memory>

#include "azt/calibration/scan_log_csv.hpp"
#include "azt/calibration/term_selection.hpp"
#include "azt/linux/append_file.hpp"
#include "calibration/calibration_sources.hpp"
#include "calibration/fit_report.hpp"
#include "calibration/scan_log_file.hpp"
#include "calibration/session_sky.hpp"
#include "common/usage_error.hpp"
#include "console/body_fields.hpp"
#include "console/daemon_console.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

constexpr const char* kHistoryFile = "pointing-history.jsonl";
constexpr const char* kScanLogFile = "scan-log.csv";

/// A refusal whose message begins with its field ("hours: must be …") as a 400 naming it.
ApiError bad_field(const std::string& message) {
  return ApiError(400, message.substr(0, message.find(':')), message);
}

/// The beam a source list is estimated for: the dish's 70 λ/D, or 1.6° without one.
double estimated_beam_deg(const DishConfig& dish, std::optional<double> freq_mhz) {
  if (!dish.dish_m || !freq_mhz) return 1.6;
  return 70.0 * (299.792458 / *freq_mhz) / *dish.dish_m;
}

/// "line 3: el_deg: …": the column, for the refusal's field.
std::string column_of(const std::string& message) {
  const auto first = message.find(": ");
  if (first == std::string::npos) return "csv";
  const auto second = message.find(": ", first + 2);
  return second == std::string::npos ? "csv" : message.substr(first + 2, second - first - 2);
}

}  // namespace

std::string DaemonConsole::state_file(const char* name) const {
  return (std::filesystem::path(p_.store.path()).parent_path() / name).string();
}

void DaemonConsole::act_measurement(const std::string& action, const json& body,
                                    const std::string& source, ActDone done) {
  if (action == "noise" || action == "noise/stop") {
    return done(ActResult{act_noise(action, body, source), std::nullopt});
  }
  if (action == "recording" || action == "recording/stop") {
    return done(ActResult{act_recording(action, body, source), std::nullopt});
  }
  if (action.rfind("calibration/", 0) == 0) {
    return act_calibration(action, body, source, std::move(done));
  }
  throw ApiError(404, "", "no such action: " + action);
}

void DaemonConsole::act_calibration(const std::string& action, const json& body,
                                    const std::string& source, ActDone done) {
  if (p_.calibration == nullptr) throw ApiError(404, "", "no calibration sessions here");
  CalibrationRunner& runner = *p_.calibration;
  if (action == "calibration/session/stop") {
    runner.stop("stopped by " + source);
    return done(ActResult{{{"calibration", runner.to_json()}}, std::nullopt});
  }
  if (action == "calibration/session") {
    const auto request = calibration_request_from(body);
    if (!request) throw bad_field(request.error().message);
    if (p_.scanner == nullptr) throw ApiError(503, "", "no receiver: set [receiver] to scan");
    if (auto ready = p_.scanner->ready(p_.monotonic_s()); !ready) {
      throw ApiError(503, "", ready.error().message);
    }
    if (p_.scanner->running()) throw ApiError(409, "", "a pointing scan is running: stop it first");
    if (p_.noise != nullptr && p_.noise->running()) {
      throw ApiError(409, "", "a noise measurement is running: stop it first");
    }
    if (runner.running()) throw ApiError(409, "", "a calibration session is running already");
    auto sky = session_sky(*request, p_.ephemeris, p_.config.sky, p_.config.receiver.dish,
                           p_.config.station);
    if (!sky) throw bad_field(sky.error().message);
    auto started = runner.start(*request, std::move(sky).value(), p_.monotonic_s(), p_.unix_s());
    if (!started) throw bad_field(started.error().message);
    p_.log(source + ": calibration session of " + std::to_string(request->sources.size()) +
           " sources");
    return done(ActResult{{{"calibration", runner.to_json()}}, std::nullopt});
  }
  if (pointing_save_pending_) throw ApiError(409, "", "a pointing model is being saved already");
  const std::string utc = utc_now_text();
  if (action == "calibration/apply") {
    const auto fit = calibration_fit();
    if (!fit) throw ApiError(409, "", fit.error().message);
    std::vector<json> records;
    const PointingHistory& history = *p_.pointing_history;
    if (history.empty()) {
      records.push_back(
          history.record(p_.config.station.corrections.model, std::nullopt, 0, "in use", utc));
    }
    records.push_back(history.record(fit->terms, fit->rms_deg, fit->observations, "fit", utc));
    if (records.size() == 2) records[1]["id"] = records[0]["id"].get<long long>() + 1;
    return save_pointing(fit->terms, records, std::move(done));
  }
  if (action == "calibration/restore") {
    const long long id = body_whole_number(body, "id", 1, 1000000000, "id must be a model's id");
    const json* model = p_.pointing_history->find(id);
    if (model == nullptr) throw ApiError(400, "id", "no model " + std::to_string(id));
    const auto terms = PointingHistory::terms_of(*model);
    if (!terms) throw ApiError(400, "id", terms.error().message);
    const json& rms = (*model)["rms_after_deg"];
    const json& scans = (*model)["scans"];
    json record = p_.pointing_history->record(
        *terms, rms.is_number() ? std::optional<double>(rms.get<double>()) : std::nullopt,
        scans.is_number_unsigned() ? scans.get<std::size_t>() : 0, "restore", utc);
    record["restored_id"] = id;
    return save_pointing(*terms, {record}, std::move(done));
  }
  throw ApiError(404, "", "no such action: " + action);
}

void DaemonConsole::save_pointing(const calibration::PointingTerms& terms,
                                  const std::vector<json>& records, ActDone done) {
  pointing_save_pending_ = true;
  save(
      "pointing",
      [terms](toml::table& root) {
        if (!root.contains("pointing")) root.insert("pointing", toml::table{});
        toml::table* t = root["pointing"].as_table();
        if (t == nullptr) throw UsageError("[pointing] is not a table");
        const auto v = terms.as_array();
        for (std::size_t i = 0; i < v.size(); ++i) {
          t->insert_or_assign(calibration::term_key(i), v.at(i));
        }
      },
      [this, records] {
        apply_live(LiveApply::Corrections);
        std::string lines;
        for (const json& r : records) {
          lines += r.dump() + "\n";
          p_.pointing_history->add(r);
        }
        auto failure = std::make_shared<std::string>();
        p_.offload(
            [path = state_file(kHistoryFile), lines, failure] {
              if (auto ok = linux_os::append_lines(path, lines); !ok) *failure = ok.error().message;
            },
            [this, failure] {
              if (!failure->empty()) p_.log("pointing history: " + *failure);
            });
        return json{{"model", records.back()}};
      },
      [this, done = std::move(done)](ActResult result) {
        pointing_save_pending_ = false;
        done(std::move(result));
      });
}

Result<calibration::PointingFit> DaemonConsole::calibration_fit() const {
  const auto& log = p_.calibration->log();
  return calibration::fit_pointing_model(calibration::observations_from_log(log),
                                         p_.config.station.corrections.model);
}

std::pair<unsigned, json> DaemonConsole::calibration_view(const std::string& route) {
  if (p_.calibration == nullptr) throw ApiError(404, "", "no calibration sessions here");
  if (route == "sources") {
    const DishConfig& dish = p_.config.receiver.dish;
    const auto freq = p_.config.sky.settings.freq_mhz;
    return {200, offers_json(offer_sources(p_.config.sky.targets, dish, freq,
                                           estimated_beam_deg(dish, freq), 4.0),
                             dish.given())};
  }
  if (route == "fit") {
    const auto fit = calibration_fit();
    if (!fit) return {409, {{"refused", fit.error().message}}};
    return {200, fit_json(*fit, p_.calibration->log())};
  }
  if (route == "history") return {200, p_.pointing_history->newest_first()};
  throw ApiError(404, "", "no such page: /api/calibration/" + route);
}

json DaemonConsole::calibration_json() const {
  json j = p_.calibration != nullptr ? p_.calibration->to_json() : json{{"state", "idle"}};
  j["model"] = terms_json(p_.config.station.corrections.model);  // [pointing], as in use
  return j;
}

std::optional<std::string> DaemonConsole::scan_log_csv() {
  if (p_.calibration == nullptr) return std::nullopt;
  return calibration::write_scan_log_csv(p_.calibration->log());
}

void DaemonConsole::import_scan_log(std::string text, const std::string& source, ActDone done) {
  if (p_.calibration == nullptr) throw ApiError(404, "", "no scan log here");
  p_.log(source + ": imports a scan log (" + std::to_string(text.size()) + " bytes)");
  auto rows = std::make_shared<Result<std::vector<calibration::ScanLogEntry>>>(fail("not read"));
  auto failure = std::make_shared<std::string>();
  p_.offload(
      [text = std::move(text), rows, failure, path = state_file(kScanLogFile)] {
        *rows = calibration::read_scan_log_csv(text);
        if (!*rows || (*rows)->empty()) return;
        std::error_code ec;
        const bool fresh =
            !std::filesystem::exists(path, ec) || std::filesystem::file_size(path, ec) == 0;
        if (auto ok = linux_os::append_lines(path, scan_log_lines(**rows, fresh)); !ok) {
          *failure = ok.error().message;
        }
      },
      [this, rows, failure, done = std::move(done)] {
        if (!*rows) {
          const std::string& why = rows->error().message;
          return done(ActResult{{}, ApiError(400, column_of(why), why)});
        }
        if (!failure->empty()) return done(ActResult{{}, ApiError(503, "", *failure)});
        p_.calibration->add_rows(**rows);
        done(ActResult{{{"imported", (*rows)->size()}, {"log_rows", p_.calibration->log().size()}},
                       std::nullopt});
      });
}

}  // namespace azt::app
