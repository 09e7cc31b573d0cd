#pragma once
// One pointing scan as it runs (docs/calibration.md), the same in the daemon and in the simulation:
// which offset to send the beam to, when the antenna has settled on it, which receiver readings
// count, and the samples the fit gets. Time is a parameter; the caller moves the antenna (source +
// offset(), the ephemeris read at every tick: the source moves during a scan) and passes on the
// receiver's readings.
//
// A point is read once the antenna stands still: the controller not driving and the encoders
// unchanged for kStillS (a reading while an axis moves, or coasts after its drive stops, pairs the
// power with a position the encoders report late). Readings are averaged in linear power for
// dwell_s of still time; a point not reached within max_settle_s is missed (the fit counts it).

#include <cstddef>
#include <optional>
#include <vector>

#include "azt/calibration/scan_fit.hpp"
#include "azt/calibration/scan_plan.hpp"
#include "azt/control/modes.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

struct ScanTiming {
  double settle_s = 1.0;        ///< still this long before the readings count
  double dwell_s = 4.0;         ///< still time over which a point's readings are averaged
  double max_settle_s = 120.0;  ///< a point not settled on by then is missed
};

/// The order to measure a plan in. A cross scan goes there and back along each line (its
/// readings then centre on one instant, the turn: the mount's error changes as the source
/// moves, so a line's offset belongs to its own moment); other scans as planned.
std::vector<ScanPoint> measuring_order(ScanKind kind, const std::vector<ScanPoint>& plan);

class ScanSession {
 public:
  static constexpr double kStillS = 0.25;

  /// Measures `spec`'s plan about `centre` (an offset already found: a refining scan), starting
  /// at `now_s`. Fails as plan_scan does.
  static Result<ScanSession> start(const ScanSpec& spec, const ScanTiming& timing,
                                   const SkyOffset& centre, double now_s);

  /// Where to point now, relative to the source; nullopt once done.
  [[nodiscard]] std::optional<SkyOffset> offset() const;

  /// One control tick. `driving`: the controller drives an axis; `encoders`: the raw readings
  /// (nullopt: none); `pointed`: where the controller believes the beam points relative to the
  /// source (its corrected reading, offset_between(source, reading); nullopt: no position).
  void tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
            const std::optional<SkyOffset>& pointed);
  /// A receiver reading taken at `now_s`; it counts while a point dwells and the antenna stands
  /// still. Returns whether it counted.
  bool reading(double now_s, double power_db);

  [[nodiscard]] bool done() const { return index_ >= points_.size(); }
  [[nodiscard]] std::size_t points_done() const { return index_; }
  [[nodiscard]] std::size_t points_total() const { return points_.size(); }
  [[nodiscard]] const std::vector<ScanSample>& samples() const { return samples_; }
  [[nodiscard]] const ScanSpec& spec() const { return spec_; }
  /// The instants the cross-elevation and the elevation line's readings centre on (set as the
  /// scan passes them): pair each line's offset with the source's position then.
  [[nodiscard]] std::optional<double> xel_moment_s() const { return xel_moment_s_; }
  [[nodiscard]] std::optional<double> el_moment_s() const { return el_moment_s_; }

  /// Fits what was measured (fit_scan).
  [[nodiscard]] Result<ScanFit> fit() const;

 private:
  ScanSession(const ScanSpec& spec, const ScanTiming& timing, const SkyOffset& centre,
              std::vector<ScanPoint> points, double now_s);
  void finish_point(double now_s);
  void note_moments(double now_s);

  ScanSpec spec_;
  ScanTiming timing_;
  SkyOffset centre_;
  std::vector<ScanPoint> points_;
  std::vector<ScanSample> samples_;
  std::size_t index_ = 0;
  double point_start_s_ = 0.0;
  std::optional<double> still_since_s_;  ///< standing still since (driving off, encoders unchanged)
  std::optional<control::AzEl> last_encoders_;
  double last_tick_s_ = 0.0;
  double dwelt_s_ = 0.0;  ///< still time counted towards dwell_s
  bool dwelling_ = false;
  bool still_ = false;
  std::optional<SkyOffset> pointed_;
  double power_sum_ = 0.0;  ///< linear
  double xel_sum_ = 0.0;
  double el_sum_ = 0.0;
  int readings_ = 0;
  std::optional<double> xel_moment_s_;
  std::optional<double> el_moment_s_;
};

}  // namespace azt::calibration
