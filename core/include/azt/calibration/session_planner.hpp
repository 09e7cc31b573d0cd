#pragma once
// The plan of a pointing calibration session (docs/calibration.md): which source to scan next so
// that the scans cover the sky the way the pointing model needs. The Sun may be scanned every N
// minutes through the day, as amateurs do; the other sources when a scan of them now would lower
// the model's expected error over the sky (sky_coverage.hpp) by a fair share: a greedy I-optimal
// design, which spreads the scans in azimuth (the tilt terms) and elevation (collimation, sag,
// the non-perpendicularity). A source is scanned only while it stays within the site's limits
// for the whole scan, clear of the azimuth stops, bright enough, and not beside another source
// the receiver hears. Deterministic: ties go to the earlier source; the clock is the caller's.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "azt/calibration/sky_coverage.hpp"
#include "azt/control/axis_geometry.hpp"
#include "azt/control/modes.hpp"

namespace azt::calibration {

struct PlanSource {
  std::string name;
  double snr_db = 0.0;  ///< the estimate of source_snr.hpp
  double size_deg = 0.0;
  /// Scanned every PlanSettings::every_s whatever the coverage (the Sun through the day).
  bool periodic = false;
};

/// Where source `index` is at `t_s` on the caller's clock (apparent az/el); nullopt: unknown.
using SourcePosition = std::function<std::optional<control::AzEl>(std::size_t index, double t_s)>;

struct SiteLimits {
  double min_el_deg = 10.0;  ///< refraction's error grows below (astronomy-and-eme.md §8)
  double max_el_deg = 80.0;  ///< the azimuth gets fast and the terms ill-conditioned above
  control::AzimuthRange az_range;
  /// The lowest clear elevation at an azimuth (a horizon mask); empty: min_el_deg everywhere.
  std::function<double(double az_deg)> horizon_el_deg;
};

struct PlanSettings {
  double scan_s = 900.0;  ///< one source's scans (search and refine), start to end
  double beamwidth_deg = 1.6;
  double half_span_beams = 2.0;   ///< the scans' reach, kept clear of the azimuth stops
  double every_s = 1800.0;        ///< the periodic sources' interval (0: by coverage as the rest)
  double min_gain = 0.01;         ///< the least share of the sky error a scan must take off
  double min_snr_db = 10.0;       ///< fainter sources are not scanned
  double confusion_beams = 4.0;   ///< closer than this to a source the receiver hears: skipped
  double confusion_snr_db = 0.0;  ///< a source this loud is heard (as loud as a point's noise)
  double retry_s = 3600.0;        ///< a source whose scans found nothing waits this long
  double wait_s = 300.0;          ///< nothing worth scanning: look again after this
  std::size_t max_scans = 60;     ///< fitted scans; then the session is done
};

struct PlannedScan {
  std::size_t source = 0;
  double t_s = 0.0;
  control::AzEl at;  ///< where the source is at t_s
};

class SessionPlanner {
 public:
  SessionPlanner(std::vector<PlanSource> sources, SourcePosition position, SiteLimits limits,
                 PlanSettings settings);

  /// The source to scan at `now_s`; nullopt: none worth it now (ask again at look_again_s).
  [[nodiscard]] std::optional<PlannedScan> next(double now_s) const;
  /// When to ask again after next() gave nothing: after wait_s, or when a periodic source is due.
  [[nodiscard]] double look_again_s(double now_s) const;
  /// max_scans fitted scans are in.
  [[nodiscard]] bool done() const { return fitted_ >= settings_.max_scans; }

  /// Source `index`'s scans ran from `started_s` to `ended_s`: `fitted`, or found nothing (then
  /// retried after retry_s from their end). A periodic source is due every_s after the start of
  /// its last scans (the Sun every 30 minutes; when another source's scans run then, after them).
  void scanned(std::size_t index, double started_s, double ended_s, bool fitted);
  /// An offset measured at `at` (a log row: a cross scan's line measures one of the two).
  void covered(const control::AzEl& at, bool xel, bool el);

  [[nodiscard]] double sky_error() const { return coverage_.sky_error(); }
  [[nodiscard]] std::size_t fitted_scans() const { return fitted_; }
  [[nodiscard]] const std::vector<PlanSource>& sources() const { return sources_; }
  [[nodiscard]] const PlanSettings& settings() const { return settings_; }
  /// Source `index` at `t_s` (the position callback).
  [[nodiscard]] std::optional<control::AzEl> position(std::size_t index, double t_s) const;
  /// The index of the source named `name`, if any.
  [[nodiscard]] std::optional<std::size_t> find(const std::string& name) const;
  /// Whether source `index` can be scanned from `t_s` for scan_s (limits, stops, brightness,
  /// neighbours, a recent failure): the planner's rules, for a caller's own choice.
  [[nodiscard]] bool usable(std::size_t index, double t_s) const;

 private:
  [[nodiscard]] bool within_limits(const control::AzEl& at) const;
  [[nodiscard]] bool clear_of_stops(const control::AzEl& at) const;
  [[nodiscard]] bool confused(std::size_t index, const control::AzEl& at, double t_s) const;
  [[nodiscard]] bool due(std::size_t index, double t_s) const;
  [[nodiscard]] bool by_period(std::size_t index) const;

  std::vector<PlanSource> sources_;
  SourcePosition position_;
  SiteLimits limits_;
  PlanSettings settings_;
  SkyCoverage coverage_;
  std::vector<std::optional<double>> last_fitted_s_;
  std::vector<std::optional<double>> last_failed_s_;
  std::size_t fitted_ = 0;
};

/// The session ahead from `start_s` to `end_s` as `planner` would run it if every scan took
/// scan_s and found its source: what the operator is shown before starting.
std::vector<PlannedScan> plan_session(SessionPlanner planner, double start_s, double end_s);

}  // namespace azt::calibration
