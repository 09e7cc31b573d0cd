#pragma once
// A pointing scan run by the daemon (docs/calibration.md): while the station tracks the scanned
// source, the demand is the source plus the scan's offset (calibration::ScanSession, the logic
// `azeltrack simulate --scenario calibrate` runs), the antenna's state and the receiver's
// readings ([receiver], station/power_receiver.hpp) go to the session each tick, and at the end
// the scan is fitted. The offsets it finds are in the Offset screen's terms, for the console's
// one-press apply. Any other command, a fault or a silent receiver ends the scan.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "azt/calibration/calibration_session.hpp"
#include "azt/calibration/power_feed.hpp"
#include "azt/calibration/scan_session.hpp"
#include "azt/control/modes.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

/// What a scan found, in mount degrees: add −az_offset_deg / −el_offset_deg to the encoder
/// offsets and the beam is on what the readings say.
struct ScanOffsets {
  double az_offset_deg = 0.0;
  double el_offset_deg = 0.0;
};

class PointingScanner {
 public:
  /// `feed`: the receiver's readings; null: no receiver (scans are refused).
  explicit PointingScanner(const calibration::PowerFeed* feed) : feed_(feed) {}

  /// Begins a scan of `source` (the station already tracks it) about `centre` (a calibration
  /// session's refining scan: about what its first found). Fails with the reason (no receiver, a
  /// silent one, a bad plan).
  Result<bool> start(const std::string& source, const calibration::ScanSpec& spec,
                     const calibration::ScanTiming& timing, double now_s,
                     const calibration::SkyOffset& centre = {});
  /// Whether a scan could start now: a receiver that is not silent.
  [[nodiscard]] Result<bool> ready(double now_s) const;
  /// The found offsets were applied: not offered again.
  void applied() { found_.reset(); }
  /// Ends a running scan, saying why ("stopped: …").
  void stop(const std::string& why);
  [[nodiscard]] bool running() const { return session_.has_value(); }
  [[nodiscard]] const std::string& source() const { return source_; }

  /// The position to demand with the source at `source_now`: the source plus the offset.
  [[nodiscard]] std::optional<control::AzEl> aim(const control::AzEl& source_now) const;

  /// After the antenna's tick: the antenna's state (`believed`: its corrected sky position,
  /// nullopt when unknown) and the readings since the last tick go to the session; at its end,
  /// the fit.
  void tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
            const std::optional<control::AzEl>& source_now,
            const std::optional<control::AzEl>& believed);

  /// The last finished scan's offsets, when it fitted.
  [[nodiscard]] std::optional<ScanOffsets> found() const;
  /// The last scan as a calibration session takes it (calibration_session.hpp): its fit, or the
  /// reason it has none (stopped, refused), and where the source was at each line's moment.
  [[nodiscard]] calibration::ScanResult result() const;
  /// idle, running, done, refused or stopped.
  [[nodiscard]] const std::string& state() const { return state_; }

  /// The console's `scan`: state (idle, running, done, refused, stopped), source, kind,
  /// points_done, points_total, samples, fit, the offsets found, the reason.
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  void finish();

  const calibration::PowerFeed* feed_;
  std::optional<calibration::ScanSession> session_;
  std::optional<calibration::ScanSession> last_;  ///< the finished or stopped scan, for display
  std::string source_;
  std::string state_ = "idle";
  std::string reason_;
  double last_reading_s_ = 0.0;
  std::optional<control::AzEl> sky_xel_;  ///< the source at the xel line's moment
  std::optional<control::AzEl> sky_el_;
  std::optional<calibration::ScanFit> fit_;
  std::optional<ScanOffsets> found_;
};

}  // namespace azt::app
