#pragma once
// The readings of one pointing (docs/calibration.md): the antenna is asked somewhere, and once it
// stands still (the controller not driving and the encoders unchanged for kStillS: a reading
// while an axis moves or coasts pairs the power with a place the encoders report late) and
// settle_s has passed, the receiver's readings are averaged in linear power over dwell_s of still
// time. A pointing not settled on within max_settle_s is missed. The same rule as a scan's points
// (scan_session.hpp); the noise measurement's on- and off-source pointings use it. Time is a
// parameter.

#include <optional>

#include "azt/calibration/scan_session.hpp"
#include "azt/control/modes.hpp"

namespace azt::calibration {

class PointDwell {
 public:
  static constexpr double kStillS = ScanSession::kStillS;

  PointDwell(const ScanTiming& timing, double now_s)
      : timing_(timing), start_s_(now_s), last_tick_s_(now_s) {}

  /// One control tick: `driving` an axis, the raw `encoders` (nullopt: none).
  void tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders);
  /// A receiver reading; counts while dwelling and still. Returns whether it counted.
  bool reading(double power_db);

  /// Dwelt long enough, or missed.
  [[nodiscard]] bool finished() const { return finished_; }
  /// The mean of the counted readings (linear power, in dB); nullopt when none counted.
  [[nodiscard]] std::optional<double> mean_db() const;
  [[nodiscard]] int readings() const { return readings_; }

 private:
  void note_stillness(double now_s, bool driving, const std::optional<control::AzEl>& encoders);

  ScanTiming timing_;
  double start_s_;
  double last_tick_s_;
  std::optional<double> still_since_s_;
  std::optional<control::AzEl> last_encoders_;
  bool still_ = false;
  bool dwelling_ = false;
  bool finished_ = false;
  double dwelt_s_ = 0.0;
  double power_sum_ = 0.0;  ///< linear
  int readings_ = 0;
};

}  // namespace azt::calibration
