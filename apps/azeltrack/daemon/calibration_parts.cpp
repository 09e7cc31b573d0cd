// The daemon's calibration session (docs/calibration.md "In the daemon"): the runner over the
// station's scanner, the scan log `scan-log.csv` and the applied models' history
// `pointing-history.jsonl` read at start (bad rows said in the journal, the rest kept), each
// scan's rows appended on the worker thread (one write and one fsync a scan), and the running
// session's request kept in `calibration-session.json` (written atomically, removed when it
// ends) so that a restart resumes it.
#include <spdlog/spdlog.h>

#include <filesystem>
#include <memory>
#include <utility>

#include "azt/linux/append_file.hpp"
#include "azt/linux/atomic_file.hpp"
#include "calibration/scan_log_file.hpp"
#include "calibration/session_sky.hpp"
#include "common/target_request.hpp"
#include "daemon/station_daemon.hpp"

namespace azt::app {
namespace {

/// At most this many of a file's bad rows are named in the journal; the rest are counted.
constexpr std::size_t kNamedBadRows = 10;

std::vector<calibration::ScanLogEntry> load_scan_log(const std::string& path) {
  if (!std::filesystem::exists(path)) return {};
  const auto text = linux_os::read_file(path);
  if (!text) {
    spdlog::error("scan log {}: {}: starting without its rows", path, text.error().message);
    return {};
  }
  LoadedScanLog loaded = read_scan_log_file(*text);
  for (std::size_t i = 0; i < loaded.refused.size() && i < kNamedBadRows; ++i) {
    spdlog::warn("scan log {}: {}: row skipped", path, loaded.refused[i]);
  }
  if (loaded.refused.size() > kNamedBadRows) {
    spdlog::warn("scan log {}: {} more bad rows skipped", path,
                 loaded.refused.size() - kNamedBadRows);
  }
  spdlog::info("scan log {}: {} rows", path, loaded.rows.size());
  return std::move(loaded.rows);
}

}  // namespace

std::unique_ptr<CalibrationRunner> StationDaemon::make_calibration_runner() {
  const std::string history = beside_config(kPointingHistoryFile);
  if (std::filesystem::exists(history)) {
    if (const auto text = linux_os::read_file(history)) {
      std::size_t skipped = 0;
      pointing_history_ = PointingHistory::parse(*text, skipped);
      if (skipped > 0) spdlog::warn("pointing history {}: {} bad lines skipped", history, skipped);
    } else {
      spdlog::error("pointing history {}: {}", history, text.error().message);
    }
  }
  CalibrationStation station{
      [this](const std::string& name) { return point_for_calibration(name); },
      [this]() -> std::optional<std::string> {
        if (modes_.mode() != control::Mode::Track || !sky_.target()) return std::nullopt;
        return sky_.target()->name;
      },
      [this] { return config_.station.corrections; },
      [this](const std::vector<calibration::ScanLogEntry>& rows) { append_scan_rows(rows); },
      [this](const nlohmann::json& record) { keep_calibration(record); }};
  return std::make_unique<CalibrationRunner>(*scanner_, std::move(station),
                                             load_scan_log(beside_config(kScanLogFile)));
}

Result<std::string> StationDaemon::point_for_calibration(const std::string& name) {
  const CommandOutcome outcome = commands_.point(
      CommandSource{CommandSource::Kind::Console, "calibration session"}, target_from_name(name));
  if (outcome.refusal) return fail(outcome.refusal->reason);
  if (!sky_.target()) return fail(name + " is not a sky source");
  return sky_.target()->name;
}

void StationDaemon::append_scan_rows(const std::vector<calibration::ScanLogEntry>& rows) {
  spdlog::info("calibration: {} rows of {} to the scan log", rows.size(), rows.front().source);
  auto failure = std::make_shared<std::string>();
  off_loop()(
      [path = beside_config(kScanLogFile), rows, failure] {
        std::error_code ec;
        const bool fresh =
            !std::filesystem::exists(path, ec) || std::filesystem::file_size(path, ec) == 0;
        if (auto ok = linux_os::append_lines(path, scan_log_lines(rows, fresh)); !ok) {
          *failure = ok.error().message;
        }
      },
      [failure] {
        if (!failure->empty()) spdlog::error("scan log: {}", *failure);
      });
}

void StationDaemon::keep_calibration(const nlohmann::json& record) {
  auto failure = std::make_shared<std::string>();
  off_loop()(
      [path = beside_config(kCalibrationSessionFile), text = record.dump(), failure] {
        if (text == "null") {
          std::error_code ec;
          std::filesystem::remove(path, ec);
          if (ec) *failure = "remove " + path + ": " + ec.message();
          return;
        }
        if (auto ok = linux_os::write_file_atomically(path, text + "\n"); !ok) {
          *failure = ok.error().message;
        }
      },
      [failure] {
        if (!failure->empty()) spdlog::error("calibration session file: {}", *failure);
      });
}

void StationDaemon::resume_calibration() {
  const std::string path = beside_config(kCalibrationSessionFile);
  if (!std::filesystem::exists(path)) return;
  const auto text = linux_os::read_file(path);
  const nlohmann::json record =
      text ? nlohmann::json::parse(*text, nullptr, false) : nlohmann::json();
  const auto request = record.is_object()
                           ? calibration_request_from(record.value("request", nlohmann::json()))
                           : Result<CalibrationRequest>(fail("not a JSON object"));
  if (!request || !record.value("started_unix_s", nlohmann::json()).is_number()) {
    spdlog::error("calibration session {}: {}: not resumed", path,
                  request ? "no started_unix_s" : request.error().message);
    keep_calibration(nlohmann::json(nullptr));
    return;
  }
  auto sky =
      session_sky(*request, *ephemeris_, config_.sky, config_.receiver.dish, config_.station);
  Result<bool> started =
      sky ? calibration_->start(*request, std::move(sky).value(), now_s(), unix_now_s(),
                                record["started_unix_s"].get<double>())
          : Result<bool>(sky.error());
  if (!started) {
    spdlog::error("calibration session {}: {}: not resumed", path, started.error().message);
    keep_calibration(nlohmann::json(nullptr));
    return;
  }
  spdlog::info("calibration session resumed: {}", calibration_->to_json().dump());
}

void StationDaemon::calibration_tick(double now) {
  if (!calibration_->running()) return;
  calibration_->tick(now);
  if (!calibration_->running()) {
    spdlog::info("calibration session: {}", calibration_->to_json().value("reason", ""));
    if (console_) console_->push_now();
  }
}

}  // namespace azt::app
