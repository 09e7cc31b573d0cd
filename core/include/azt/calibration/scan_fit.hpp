#pragma once
// What a pointing scan found (docs/calibration.md; astronomy-and-eme.md §8): a Gaussian beam plus a
// baseline fitted to the measured power, in linear units (the power of a Gaussian beam on a
// source falls as a Gaussian of the offset; in dB it would not be). The centre is the offset
// that puts the beam on the source; the width is the beam convolved with the source.
// A scan with too few good readings, or no clear peak inside it, is refused with the reason.

#include <cstddef>
#include <optional>
#include <vector>

#include "azt/calibration/scan_plan.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

/// One point of a scan: where it was commanded, and the power read there (dB on any fixed
/// scale); nullopt when the reading was missing or malformed.
struct ScanSample {
  ScanPoint point;
  std::optional<double> power_db;
  /// Where the antenna pointed, relative to the source, by its encoders (a controller holds a
  /// position within its window, not exactly on the point); nullopt: at point.offset. The fit
  /// uses it as the coordinate; the planned point decides which line a reading belongs to.
  std::optional<SkyOffset> pointed;
};

/// One line's fitted curve in linear power (10^(dB/10)) against the line's offset s, degrees:
/// p(s) = baseline + slope·(s − centre) + amplitude·exp(−4 ln2 (s − centre)²/width²), with the
/// line's centre and width from ScanFit (a raster's: its round beam cut through the centre).
struct LineCurve {
  double baseline = 0.0;  ///< at the centre
  double slope = 0.0;     ///< per degree (0 for a five-point scan or a raster)
  double amplitude = 0.0;
};

struct ScanFit {
  SkyOffset peak;              ///< add this to the ephemeris to put the beam on the source
  SkyOffset peak_std;          ///< the fit's standard error of each (0 for a five-point scan)
  double width_xel_deg = 0.0;  ///< measured full width at half maximum, cross-elevation
  double width_el_deg = 0.0;   ///< and in elevation (the same for a raster's round beam)
  double peak_db = 0.0;        ///< the source's rise above the baseline (Y-factor), dB
  double noise_db = 0.0;       ///< rms of the fit's residuals in dB (0 for a five-point scan)
  std::size_t used = 0;        ///< good readings fitted
  std::size_t missing = 0;     ///< readings missing or malformed
  LineCurve xel_curve;         ///< what the console draws over the readings
  LineCurve el_curve;
};

/// The fewest good readings a line (cross), a grid (raster) or a five-point scan needs.
constexpr std::size_t kMinPointsPerLine = 7;
constexpr std::size_t kMinRasterPoints = 12;

/// Fits the scan. `beamwidth_deg` is the expected HPBW (the starting width and the scale of the
/// checks). Refused when: too few good readings; the fit does not converge; the peak is not at
/// least 5 noise rms above the baseline; the peak lies outside the scanned offsets; the width is
/// below 0.3 beamwidths or wider than the scan.
Result<ScanFit> fit_scan(ScanKind kind, const std::vector<ScanSample>& samples,
                         double beamwidth_deg);

/// Removes the source's size from a measured width: W_beam² = W_meas² − θ_source² (Gaussian
/// deconvolution, astronomy-and-eme.md §8 step 5); 0 when the source is wider than measured.
double deconvolved_beamwidth_deg(double measured_deg, double source_deg);

}  // namespace azt::calibration
