#pragma once
// Recording for offline analysis (docs/calibration.md "Recording"): the pointing (demand, reading,
// error) and the receiver's power, one CSV row at a chosen rate, taken on the control loop and
// handed on in batches for the worker thread to append, so the loop never waits for the disk.
// Pure bookkeeping: time is a parameter (the loop's monotonic seconds), the file is the caller's
// `Write`. A size cap ends a recording with the reason, so a forgotten one cannot fill the disk.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "azt/control/modes.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

/// One moment of the station as a row records it; a part unknown then is left empty.
struct RecordingSample {
  double unix_s = 0.0;                   ///< UTC, seconds since 1970
  std::optional<control::AzEl> demand;   ///< where the controller was sent (none: holding)
  std::optional<control::AzEl> reading;  ///< where the beam points as read (corrected)
  std::optional<double> power_db;        ///< the receiver's newest fresh reading
  std::string mode;                      ///< TRACK, MAN, PARK, EXT, STOP
};

struct RecorderLimits {
  double min_rate_hz = 0.1;
  double max_rate_hz = 50.0;
  /// A batch goes to the worker when it holds this many rows or is this old.
  std::size_t batch_rows = 250;
  double batch_s = 2.0;
};

/// The recording's file name for a start at `unix_s`: "recording-20261129T163500Z.csv".
std::string recording_file_name(double unix_s);
/// Whether `name` is one recording_file_name() makes (the downloads take no other: no path).
bool is_recording_file_name(const std::string& name);
/// The CSV's header line (no newline).
const char* recording_csv_header();

class Recorder {
 public:
  /// `write(name, text, first)`: append `text` to the recording `name` (`first`: create it; the
  /// caller runs it off the loop, in order).
  using Write = std::function<void(const std::string& name, std::string text, bool first)>;

  explicit Recorder(Write write, RecorderLimits limits = {})
      : write_(std::move(write)), limits_(limits) {}

  /// Starts a recording at `rate_hz` capped at `max_bytes`; fails naming the field, or while
  /// one runs.
  Result<bool> start(double rate_hz, std::size_t max_bytes, double now_s, double unix_s);
  /// Ends a running recording (its rows written), saying why.
  void stop(const std::string& why);
  /// Each control tick: takes a row when one is due at `rate_hz`.
  void sample(double now_s, const RecordingSample& sample);
  /// The worker could not write `name`: the recording ends with the reason.
  void write_failed(const std::string& name, const std::string& why);
  [[nodiscard]] bool running() const { return state_ == "recording"; }

  /// The console's `recording`: {state (idle, recording, stopped, failed), file, rows, bytes,
  /// rate_hz, max_bytes, reason}.
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  void take(const RecordingSample& sample);
  void flush();

  Write write_;
  RecorderLimits limits_;
  std::string state_ = "idle";
  std::string file_;
  std::string reason_;
  std::string batch_;  ///< rows not yet handed to the worker
  std::size_t batch_count_ = 0;
  bool first_ = true;  ///< the next batch creates the file
  double rate_hz_ = 0.0;
  std::size_t max_bytes_ = 0;
  std::size_t rows_ = 0;
  std::size_t bytes_ = 0;  ///< taken, header included
  double next_s_ = 0.0;    ///< when the next row is due
  double batch_start_s_ = 0.0;
};

}  // namespace azt::app
