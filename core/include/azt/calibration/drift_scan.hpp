#pragma once
// A drift scan as it runs (docs/calibration.md "Drift scans"), the same in the daemon and in
// `azeltrack simulate --scenario drift`: the beam is put on the source's path `ahead_beams`
// beamwidths ahead of it and the drives stand still while the sky carries the source through
// the beam and as far out the other side; the power against time gives the beamwidth and the
// pointing error along the path, independent of the drives (drift_fit.hpp).
//
// Time is a parameter. At the start the caller gives the source's rate across the sky (a star's
// sidereal_drift_rate_deg_s, the Sun's or the Moon's from the ephemeris); the session says when
// the source will reach the beam (transit_s()): the caller points at the source's place at that
// instant, once, and holds there. Each tick it passes the antenna's state and where the source
// is now relative to where it believes the beam points, in the plane tangent to the sky at the
// beam (offset_between(corrected reading, source)): with the beam still, that frame stands still
// too, and the source's path in it is the straight line the fit assumes. (In the plane at the
// source, whose azimuth axis turns as the source moves, a path 24° from the zenith bends by a
// quarter of a degree across a drift.) Each receiver reading is binned. Recording starts once the
// antenna has stood still for settle_s (the readings of a moving antenna do not count) and ends
// ahead_beams beamwidths after the transit.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "azt/calibration/drift_fit.hpp"
#include "azt/calibration/pointing_model.hpp"
#include "azt/control/modes.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

struct DriftSpec {
  double beamwidth_deg = 1.0;  ///< the expected half-power beamwidth
  double ahead_beams = 3.0;    ///< the beam waits this many beamwidths ahead of the source
  double slew_s = 120.0;       ///< time allowed to reach the point (the transit is this much later)
  double settle_s = 2.0;       ///< still this long before recording
  double bin_s = 2.0;          ///< readings averaged over intervals this long

  static constexpr double kMaxDurationS = 4.0 * 3600.0;
};

enum class DriftPhase { Slewing, Recording, Done, Failed };

class DriftScan {
 public:
  /// Fails, naming the field, on a beamwidth outside (0, 30]°, ahead_beams outside [1.5, 10],
  /// slew_s outside [0, 3600] s, settle_s outside [0, 60] s, bin_s outside [0.2, 60] s, a rate
  /// not above 1e-5 °/s, or a drift that would last over four hours.
  static Result<DriftScan> start(const DriftSpec& spec, double rate_deg_s, double now_s);

  /// When the source reaches the point to hold (point the antenna at its place then).
  [[nodiscard]] double transit_s() const { return transit_s_; }
  /// When the recording ends.
  [[nodiscard]] double end_s() const { return end_s_; }

  /// One control tick (header): `source_from_beam` is offset_between(believed beam, source).
  void tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
            const std::optional<SkyOffset>& source_from_beam);
  /// A receiver reading at `now_s`; binned while recording and still. Returns whether it counted.
  bool reading(double now_s, double power_db);

  [[nodiscard]] DriftPhase phase() const { return phase_; }
  [[nodiscard]] bool done() const {
    return phase_ == DriftPhase::Done || phase_ == DriftPhase::Failed;
  }
  /// Why it failed (DriftPhase::Failed).
  [[nodiscard]] const std::string& reason() const { return reason_; }
  [[nodiscard]] const std::vector<DriftBin>& bins() const { return bins_; }
  [[nodiscard]] const DriftSpec& spec() const { return spec_; }

  /// Fits what was recorded (fit_drift); refused with the reason when the scan failed.
  [[nodiscard]] Result<DriftFit> fit() const;

 private:
  DriftScan(const DriftSpec& spec, double rate_deg_s, double now_s);
  void begin_recording(double now_s);
  void close_bin();

  DriftSpec spec_;
  double rate_deg_s_;
  double transit_s_;
  double end_s_;
  DriftPhase phase_ = DriftPhase::Slewing;
  std::string reason_;
  std::optional<double> still_since_s_;
  std::optional<control::AzEl> last_encoders_;
  bool still_ = false;
  std::optional<SkyOffset> pointed_;
  double record_start_s_ = 0.0;
  std::vector<DriftBin> bins_;
  std::size_t bin_index_ = 0;  ///< the interval the open bin collects
  DriftBin open_;              ///< sums until closed
};

}  // namespace azt::calibration
