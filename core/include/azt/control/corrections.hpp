#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "azt/util/result.hpp"

namespace azt::control {

// Position corrections of the AnTrack-Pro manual (seed 000, "SECTION B (antenna correction, tilt
// table and AZ/EL corrections in 0,01 deg step …)"), applied to the measured position in the
// seed's order: encoder offset → user correction → tilt table.
//
// Sign conventions, all in degrees:
//  * Encoder offset and tilt entries are CALIBRATIONS OF THE READING: the value added to what the
//    encoder says to get where the antenna is. The seed's worked example: the antenna is at 0° of
//    elevation, the encoder reads −3.40, and an offset of +3.40 makes it read 0.00.
//  * User corrections (the ± / UP / DWN buttons) are POINTING corrections: +0.01 in elevation makes
//    the antenna point 0.01° higher, +0.01 in azimuth 0.01° further clockwise. The seed says they
//    "are introduced directly to the antenna" to peak the signal, and an operator pressing UP
//    expects the dish to go up. They are therefore SUBTRACTED from the reading: the controller
//    drives the corrected reading onto the target, so the encoder ends up `total` above it.
//
// Why on the reading and not on the target (the two point the antenna identically): the corrected
// reading is then the best estimate of where the beam points, so everything that reads the
// position back — the display, rotctld `p`, GS-232 `C2`, the supervisor's limits — agrees with the
// target while tracking; a client that compares its command with the read-back sees no permanent
// error, and every mode (TRACK, MAN, PARK, EXT) gets the same pointing model from one place.

/// Azimuth wrapped to [0, 360) (sky azimuth; mount angles past 360 are the geometry's business).
double normalize_az_deg(double az_deg);

/// Elevation wrapped to [−90, 270): an elevation encoder turns through 0–360, so 356.60 is
/// −3.40 (below the horizon); 0–180 flip mounts stay as they are.
double normalize_el_deg(double el_deg);

/// The "Offset" screen (seed: "Antenna Correction"): per-axis degrees added to the encoder reading
/// so that it reads the true position. Lets the encoders be mounted at any angle.
struct AxisOffsets {
  double az_deg = 0.0;
  double el_deg = 0.0;

  static constexpr double kMaxAzDeg = 360.0;  ///< an encoder can be mounted at any angle
  static constexpr double kMaxElDeg = 180.0;

  /// Validates: finite, |az| ≤ 360, |el| ≤ 180.
  static Result<AxisOffsets> make(double az_deg, double el_deg);
};

/// The ± (azimuth) and UP / DWN (elevation) buttons and their running totals, in the seed's 0.01°
/// steps. Totals are kept as integer hundredths so that any sequence of presses gives exactly the
/// decimal total the display shows (10 000 presses of +0.01 are 100.00, not 99.99999999999…).
class UserCorrections {
 public:
  static constexpr double kStepDeg = 0.01;
  /// A larger pointing correction means the offsets are wrong: fix those instead.
  static constexpr std::int32_t kMaxSteps = 1000;  ///< ±10.00°

  UserCorrections() = default;

  /// Totals from degrees (a stored configuration), rounded to the nearest 0.01°. Fails on
  /// non-finite values or beyond ±10.00°.
  static Result<UserCorrections> from_deg(double az_deg, double el_deg);

  /// Adds `steps` × 0.01° (+1: the ± button's "+", clockwise). Saturates at ±kMaxSteps; returns
  /// false when the limit cut the step short.
  bool nudge_az(std::int32_t steps);
  /// Adds `steps` × 0.01° (+1: UP, −1: DWN). Saturates like nudge_az.
  bool nudge_el(std::int32_t steps);
  void reset();

  [[nodiscard]] std::int32_t az_steps() const { return az_steps_; }
  [[nodiscard]] std::int32_t el_steps() const { return el_steps_; }
  /// Pointing correction in degrees: + points the antenna clockwise.
  [[nodiscard]] double az_deg() const;
  /// Pointing correction in degrees: + points the antenna higher.
  [[nodiscard]] double el_deg() const;

 private:
  std::int32_t az_steps_ = 0;
  std::int32_t el_steps_ = 0;
};

/// The seed's tilt correction table: "60 correction positions in EL every 6 degrees of AZ" for a
/// mast that is not quite vertical. Entry i holds the elevation correction at azimuth 6·i degrees
/// (entry 0 at 000°, entry 59 at 354°), added to the reading like the offset (same screen, same
/// sense). Between entries the correction is interpolated linearly; past 354° it interpolates
/// towards entry 0 at 360°. (The seed's table prints its last labels as 296 and 360: typos for 294
/// and 354 — ten rows of six columns at a 6° step, and 360 would repeat 000.)
class TiltTable {
 public:
  static constexpr std::size_t kEntries = 60;
  static constexpr double kSpacingDeg = 6.0;
  /// A tilt beyond this is an installation to fix, not to calibrate (and a likely typing error).
  static constexpr double kMaxCorrectionDeg = 5.0;

  /// All zero: no correction.
  TiltTable() = default;

  /// Exactly 60 finite entries with |x| ≤ 5°.
  static Result<TiltTable> make(const std::vector<double>& entries_deg);

  /// Replaces one entry (index 0–59) with the same checks.
  Result<TiltTable> with_entry(std::size_t index, double correction_deg) const;

  [[nodiscard]] const std::array<double, kEntries>& entries_deg() const { return entries_deg_; }

  /// The elevation correction at any azimuth (wrapped to [0, 360) first).
  [[nodiscard]] double correction_el_deg(double az_deg) const;

 private:
  std::array<double, kEntries> entries_deg_{};
};

/// Everything the Offset / ± / UP / DWN / tilt screens configure, and the fitted pointing model
/// ([pointing], docs/calibration.md: where the beam really points for what the encoders read).
struct PositionCorrections {
  AxisOffsets offsets;
  UserCorrections user;
  TiltTable tilt;
  calibration::PointingTerms model;
};

/// The corrected reading, and the tilt correction that went into it (for display).
struct CorrectedPosition {
  double az_deg = 0.0;        ///< [0, 360)
  double el_deg = 0.0;        ///< [−90, 270)
  double tilt_el_deg = 0.0;   ///< the tilt table's contribution
  double model_az_deg = 0.0;  ///< the pointing model's contribution
  double model_el_deg = 0.0;
};

/// Applies, in the seed's order: encoder offset (added), then the pointing model (the offset
/// reading is the mount's angles; the model says where the beam points for them), user
/// correction (subtracted: see the sign conventions above), tilt (added; looked up at the
/// azimuth corrected by the steps before, because the table is indexed by where the antenna
/// really points). The model and the tilt table overlap (AN and AW are a tilt): a station that
/// fits the model leaves the table at zero.
CorrectedPosition apply_corrections(double raw_az_deg, double raw_el_deg,
                                    const PositionCorrections& corrections);

}  // namespace azt::control
