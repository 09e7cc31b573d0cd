#pragma once
// A pointing calibration session run by the daemon (docs/calibration.md "In the daemon"): the
// core's CalibrationSession and SessionPlanner, the code `simulate --scenario calibrate` runs,
// with the station's scanner (station/pointing_scanner.hpp) doing each scan. Each tick, when no
// scan runs, the session says what to do: point at a source and scan it, wait, or end. Every
// scan that found its source becomes rows of the scan log, handed to the station to append to
// the log file (off the loop). The session's clock is the control loop's (seconds), with its
// UTC known; a session whose request was kept resumes after a restart from the log's rows since
// it began.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/calibration/calibration_session.hpp"
#include "azt/control/corrections.hpp"
#include "calibration/calibration_request.hpp"
#include "station/pointing_scanner.hpp"

namespace azt::app {

/// The sources a session may scan and where they are.
struct SessionSky {
  std::vector<calibration::PlanSource> sources;
  /// Source `index` at UTC `unix_s` (apparent az/el); nullopt: unknown.
  std::function<std::optional<control::AzEl>(std::size_t index, double unix_s)> at_unix;
  calibration::SiteLimits limits;
};

/// What the session needs of the station.
struct CalibrationStation {
  /// Points the station at the source named; the name it tracks it by, or why it cannot.
  std::function<Result<std::string>(const std::string& name)> point;
  /// The source the station tracks now (none: another mode): between scans, a target other than
  /// the session's means the operator (or a program) took the station, which ends the session.
  std::function<std::optional<std::string>()> tracked;
  /// The station's corrections now (the rows record what the mount's angles were).
  std::function<control::PositionCorrections()> corrections;
  /// A scan's rows, to append to the log file.
  std::function<void(const std::vector<calibration::ScanLogEntry>&)> append;
  /// The running session's record to keep ({"request", "started_unix_s"}), or null: it ended.
  std::function<void(const nlohmann::json& record)> keep;
};

class CalibrationRunner {
 public:
  /// `log`: the scan log's rows so far (the file's).
  CalibrationRunner(PointingScanner& scanner, CalibrationStation station,
                    std::vector<calibration::ScanLogEntry> log)
      : scanner_(scanner), station_(std::move(station)), log_(std::move(log)) {}

  /// Begins a session at `now_s` on the loop's clock, whose UTC is `unix_s`; `started_unix_s`
  /// when it resumes one begun earlier (its rows since count). Fails with the reason.
  Result<bool> start(const CalibrationRequest& request, const SessionSky& sky, double now_s,
                     double unix_s, std::optional<double> started_unix_s = std::nullopt);
  /// Ends a running session (and its scan), saying why.
  void stop(const std::string& why);
  /// After the station's tick: a finished scan's rows, the next step.
  void tick(double now_s);
  /// Rows imported (already appended to the file).
  void add_rows(const std::vector<calibration::ScanLogEntry>& rows);

  [[nodiscard]] bool running() const { return session_.has_value(); }
  [[nodiscard]] const std::vector<calibration::ScanLogEntry>& log() const { return log_; }
  /// /api/state `calibration`: state, reason, plan, scans_done, scans_planned, current, log_rows,
  /// last_rows.
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  void scan_ended(double now_s);
  void begin_scan(const calibration::SessionStep& step, double now_s);
  void finish(const std::string& state, const std::string& why);
  [[nodiscard]] std::vector<calibration::ScanLogEntry> rows_since(double unix_s) const;

  PointingScanner& scanner_;
  CalibrationStation station_;
  std::vector<calibration::ScanLogEntry> log_;
  std::optional<calibration::CalibrationSession> session_;
  CalibrationRequest request_;
  std::string state_ = "idle";
  std::string reason_;
  double epoch_unix_s_ = 0.0;  ///< the UTC of the loop's clock at 0
  double end_unix_s_ = 0.0;
  double wait_until_s_ = 0.0;
  double silent_since_s_ = -1.0;  ///< the receiver silent when a scan was due, since
  bool scanning_ = false;
  std::optional<calibration::SessionStep> current_;
  std::optional<std::string> pointed_;  ///< what the session last pointed the station at
  std::size_t planned_ = 0;
  std::size_t done_ = 0;  ///< the last session's scans, once it ended
};

/// The session's scan log row as /api/state shows it.
nlohmann::json log_row_json(const calibration::ScanLogEntry& row);

}  // namespace azt::app
