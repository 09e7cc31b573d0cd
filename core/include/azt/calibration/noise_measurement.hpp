#pragma once
// A noise measurement as it runs (docs/calibration.md "Sun noise and the figure of merit"), the
// same in the daemon and in `azeltrack simulate --scenario sun-noise`: the power with the beam on
// the source, then with it `offset_beams` beamwidths off in cross-elevation (cold sky: along the
// azimuth, so at the source's elevation and through the same air), on again, then off on the
// other side, `repeats` times. Each on/off pair is one Y-factor; the sides alternate so that a
// sky brighter on one side than the other averages out. The result is their mean in dB with its
// standard error (the scatter of the pairs over √n).
//
// Time is a parameter. The caller points the antenna at source + offset() (the ephemeris read at
// every tick) and passes on its state and the receiver's readings; each pointing is read as a
// scan's point is (point_dwell.hpp).

#include <cstddef>
#include <optional>
#include <vector>

#include "azt/calibration/point_dwell.hpp"
#include "azt/calibration/pointing_model.hpp"
#include "azt/calibration/scan_session.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

struct NoisePlan {
  double beamwidth_deg = 1.0;  ///< half-power beamwidth
  double offset_beams = 3.0;   ///< the cold-sky pointings this many beamwidths off
  std::size_t repeats = 4;     ///< on/off pairs
  SkyOffset centre;  ///< where the beam is on the source (a scan's peak; 0: the ephemeris)

  static constexpr double kMinOffsetBeams = 2.0;  ///< a Gaussian beam's main lobe is 1e-5 there
  static constexpr double kMaxOffsetBeams = 20.0;
  static constexpr std::size_t kMinRepeats = 2;  ///< a scatter needs two
  static constexpr std::size_t kMaxRepeats = 50;
};

struct NoiseStep {
  bool on = true;
  int side = 0;  ///< off-source: +1 towards increasing azimuth, −1 the other way; on: 0
  SkyOffset offset;
  std::optional<double> power_db;  ///< the pointing's mean reading; nullopt: missed
  int readings = 0;
};

struct NoiseResult {
  double y_db = 0.0;          ///< mean of the pairs' Y-factors
  double std_error_db = 0.0;  ///< their standard deviation over √pairs
  double on_db = 0.0;         ///< mean power on the source (linear mean, the receiver's scale)
  double off_db = 0.0;        ///< and on cold sky
  std::vector<double> pair_y_db;
  std::size_t missed = 0;  ///< pointings without a reading
};

class NoiseMeasurement {
 public:
  /// Fails, naming the field, on a beamwidth outside (0, 30]°, an offset outside [2, 20]
  /// beamwidths, repeats outside 2–50, or timing as a scan's (ScanSession::start).
  static Result<NoiseMeasurement> start(const NoisePlan& plan, const ScanTiming& timing,
                                        double now_s);

  /// Where to point now, relative to the source; nullopt once done.
  [[nodiscard]] std::optional<SkyOffset> offset() const;
  /// One control tick: `driving` an axis, the raw `encoders` (nullopt: none).
  void tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders);
  /// A receiver reading; counts while a pointing dwells and the antenna stands still.
  bool reading(double power_db);

  [[nodiscard]] bool done() const { return index_ >= steps_.size(); }
  [[nodiscard]] std::size_t steps_done() const { return index_; }
  [[nodiscard]] const std::vector<NoiseStep>& steps() const { return steps_; }
  [[nodiscard]] const NoisePlan& plan() const { return plan_; }

  /// The Y-factor of what was measured. Fails with the reason when fewer than two on/off pairs
  /// were read (the missed pointings counted in the message).
  [[nodiscard]] Result<NoiseResult> result() const;

 private:
  NoiseMeasurement(const NoisePlan& plan, const ScanTiming& timing, double now_s);

  NoisePlan plan_;
  ScanTiming timing_;
  std::vector<NoiseStep> steps_;
  std::size_t index_ = 0;
  PointDwell dwell_;
};

}  // namespace azt::calibration
