#pragma once
// What the web console may see and do, as the HTTP API asks for it (docs/web-api.md): the state,
// the configuration, the targets and sky, and actions answered once, at once or later. The
// daemon's implementation is DaemonConsole (daemon_console.hpp); tests and the fuzzer use fakes.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "config/schema_json.hpp"

namespace azt::app {

/// A refused action: HTTP status (400 for a bad value, 409 for "not now"), the field at fault.
class ApiError : public std::runtime_error {
 public:
  ApiError(unsigned status, std::string field, const std::string& message)
      : std::runtime_error(message), status_(status), field_(std::move(field)) {}
  [[nodiscard]] unsigned status() const { return status_; }
  [[nodiscard]] const std::string& field() const { return field_; }

 private:
  unsigned status_;
  std::string field_;
};

/// What an action came to: the fields to add to {"ok": true}, or its refusal.
struct ActResult {
  nlohmann::json fields = nlohmann::json::object();
  std::optional<ApiError> error;
};
using ActDone = std::function<void(ActResult)>;

class ConsoleModel {
 public:
  ConsoleModel() = default;
  ConsoleModel(const ConsoleModel&) = delete;
  ConsoleModel& operator=(const ConsoleModel&) = delete;
  virtual ~ConsoleModel() = default;

  virtual nlohmann::json state() = 0;
  virtual nlohmann::json config() = 0;
  /// GET /api/config/schema: every setting's description; a model over a configuration file adds
  /// the file's values and the keys waiting for a restart.
  virtual nlohmann::json config_schema() { return schema_json(); }
  virtual nlohmann::json targets() = 0;
  virtual nlohmann::json sky(double hours) = 0;
  /// GET /api/schedule: the satellite schedule's list and plan; 404 where there is none.
  virtual nlohmann::json schedule() { throw ApiError(404, "", "no satellite schedule here"); }
  /// `action` is the route after "/api/" ("target", "stop", "config/tilt", …); `source` names
  /// who asked ("console 192.168.1.20") for the station's record of commands. Throws ApiError
  /// for a refusal known at once; otherwise calls `done` exactly once, at once or later (a save
  /// finishes off the event loop), always on the loop's thread.
  virtual void act(const std::string& action, const nlohmann::json& body, const std::string& source,
                   ActDone done) = 0;
  /// GET /api/moon-windows?QUERY (docs/eme.md): the common Moon windows with a DX station, which
  /// take a fraction of a second to find, so answered later (off the loop); the same contract as
  /// act(). A model without a planner refuses with 404.
  virtual void moon_windows(const std::string& query, ActDone done) {
    (void)query;
    const ActDone answer = std::move(done);
    answer(ActResult{{}, ApiError(404, "", "no Moon planner here")});
  }
  /// The account's settings, saved for the HTTP API once it has checked who asks (account_api):
  /// the password's new hash, and the API tokens' records as they are to be. Never reachable as
  /// an action of their own. A model without a file refuses with 404.
  virtual void save_password_hash(const std::string& hash, ActDone done) {
    (void)hash;
    const ActDone answer = std::move(done);
    answer(ActResult{{}, ApiError(404, "", "no settings file here")});
  }
  virtual void save_tokens(const nlohmann::json& tokens, ActDone done) {
    (void)tokens;
    const ActDone answer = std::move(done);
    answer(ActResult{{}, ApiError(404, "", "no settings file here")});
  }
  /// POST /api/satellites/elements: an operator's element file (TLE or OMM), checked as a
  /// download is and merged into the catalogue (docs/satellites.md). A model without an element
  /// feed refuses with 404. The text is taken by value: the daemon's moves it on to the worker.
  // NOLINTNEXTLINE(performance-unnecessary-value-param): this default only refuses
  virtual void upload_elements(std::string /*text*/, const std::string& /*source*/, ActDone done) {
    const ActDone answer = std::move(done);
    answer(ActResult{{}, ApiError(404, "", "no element feed here")});
  }
  /// GET routes answered off the loop from files of the state directory (docs/web-api.md):
  /// `route` after "/api/" ("recordings", "recordings/NAME", "noise/log"). The fields are the
  /// JSON answer, or a file to download: {"download": name, "content_type", "text"}. The same
  /// contract as act(). A model without them refuses with 404.
  virtual void read_later(const std::string& route, ActDone done) {
    const ActDone answer = std::move(done);
    answer(ActResult{{}, ApiError(404, "", "no such page: /api/" + route)});
  }
  /// GET /api/calibration/ROUTE (sources, fit, history; docs/web-api.md): the status and body.
  /// A model without a calibration session refuses with 404.
  virtual std::pair<unsigned, nlohmann::json> calibration_view(const std::string& route) {
    throw ApiError(404, "", "no calibration here: " + route);
  }
  /// GET /api/calibration/log: the scan log as CSV; nullopt: none here (404).
  virtual std::optional<std::string> scan_log_csv() { return std::nullopt; }
  /// POST /api/calibration/log: a CSV's rows appended to the scan log (the text moves on to the
  /// worker). A model without a scan log refuses with 404.
  // NOLINTNEXTLINE(performance-unnecessary-value-param): this default only refuses
  virtual void import_scan_log(std::string /*text*/, const std::string& /*source*/, ActDone done) {
    const ActDone answer = std::move(done);
    answer(ActResult{{}, ApiError(404, "", "no scan log here")});
  }
  /// The time now as ISO 8601 UTC, for records that say when they were made ("" unknown).
  virtual std::string utc_now_text() { return ""; }
  /// GET /api/config/file: the settings file's text; PUT: a whole file to take instead.
  virtual std::optional<std::string> config_file_text() { return std::nullopt; }
  virtual void import_config_file(const std::string& text, ActDone done) {
    (void)text;
    const ActDone answer = std::move(done);
    answer(ActResult{{}, ApiError(404, "", "no settings file here")});
  }
};

}  // namespace azt::app
