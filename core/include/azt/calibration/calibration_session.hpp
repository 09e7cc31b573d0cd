#pragma once
// A pointing calibration session (docs/calibration.md), the same in the daemon and in `azeltrack
// simulate --scenario calibrate`: the planner (session_planner.hpp) picks each source; a source
// gets the operator's kind of scan, a raster a beamwidth apart to find it when that finds
// nothing, then the kind again centred on what was found; a source found becomes rows of the
// scan log (scan_log.hpp). The caller runs each scan (ScanSession) with its antenna and
// receiver, tells the session how it ended, and appends the rows it returns to its log. The
// clock is the caller's: seconds, with the UTC of t = 0 given. A session built with the rows of
// an earlier one (a restart) carries on from them.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "azt/astro/time_scales.hpp"
#include "azt/calibration/scan_log.hpp"
#include "azt/calibration/scan_session.hpp"
#include "azt/calibration/session_planner.hpp"
#include "azt/control/corrections.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

struct SessionSetup {
  ScanSpec spec;  ///< the operator's scan: kind, beamwidth, points, span
  ScanTiming timing;
  bool refine = true;                        ///< scan again centred on the first scan's result
  astro::UtcInstant epoch;                   ///< the UTC of t = 0 on the caller's clock
  control::PositionCorrections corrections;  ///< the station's, while it scans
};

/// What the caller does now.
struct SessionStep {
  enum class Kind {
    Scan,  ///< run a scan of `source` with `spec` about `centre`
    Wait,  ///< nothing worth scanning: ask again at `until_s`
    Done,  ///< the planner's scans are all in
  };
  Kind kind = Kind::Wait;
  std::size_t source = 0;
  ScanSpec spec;
  SkyOffset centre;
  double until_s = 0.0;
};

/// How a scan ended: its fit and where the source was when each of its lines centred.
struct ScanResult {
  Result<ScanFit> fit = fail("not scanned");
  std::optional<double> xel_moment_s;
  std::optional<double> el_moment_s;
  std::optional<control::AzEl> sky_xel;
  std::optional<control::AzEl> sky_el;
};

/// One source's scans, as they ended.
struct SourceScans {
  std::size_t source = 0;
  std::string name;
  double started_s = 0.0;
  double ended_s = 0.0;
  std::size_t scans = 0;  ///< run for this source (first, search, refine)
  std::optional<ScanFit> fit;
  std::string refused;  ///< why nothing was found, when nothing was
  control::AzEl sky_xel;
  control::AzEl sky_el;
};

class CalibrationSession {
 public:
  /// `earlier`: the rows of the session's log so far (a restart): they count as scanned.
  CalibrationSession(SessionPlanner planner, const SessionSetup& setup,
                     const std::vector<ScanLogEntry>& earlier = {});

  /// What to do at `now_s`. While a scan runs, the same Scan step.
  SessionStep next(double now_s);
  /// Scans source `index` now, whatever the plan says (the operator's choice, or one scan in
  /// simulation). False while a source is being scanned or for an unknown index.
  bool begin(std::size_t index, double now_s);
  /// The scan of the last Scan step ended at `now_s`. Returns the rows to append to the log
  /// (none unless this ended the source's scans and found it).
  std::vector<ScanLogEntry> scan_ended(double now_s, const ScanResult& result);
  /// The station's corrections changed (rows already made keep theirs).
  void set_corrections(const control::PositionCorrections& c) { setup_.corrections = c; }

  [[nodiscard]] bool scanning() const { return phase_ != Phase::Idle; }
  [[nodiscard]] const std::vector<SourceScans>& history() const { return history_; }
  [[nodiscard]] const std::vector<ScanLogEntry>& log() const { return log_; }
  [[nodiscard]] const SessionPlanner& planner() const { return planner_; }

  /// The raster that looks for a source a scan missed: 7 × 7 points a beamwidth apart.
  static ScanSpec search_spec(const ScanSpec& spec);
  /// About how long one source's scans take when the first finds it (each point: settle, dwell,
  /// the still time and about a second to move): the planner's scan_s.
  static double expected_source_s(const SessionSetup& setup);

 private:
  enum class Phase { Idle, First, Search, Refine };

  SessionStep scan_step() const;
  std::vector<ScanLogEntry> finish(double now_s, const ScanResult& result);
  void resume(const std::vector<ScanLogEntry>& earlier);

  SessionPlanner planner_;
  SessionSetup setup_;
  Phase phase_ = Phase::Idle;
  SourceScans current_;
  ScanSpec spec_;
  SkyOffset centre_;
  std::vector<SourceScans> history_;
  std::vector<ScanLogEntry> log_;
};

}  // namespace azt::calibration
