#pragma once
// What a drift scan found (docs/calibration.md "Drift scans"): the beam stood still while the
// source drifted through it, so the power against time is the beam's Gaussian cut along the
// source's path. A Gaussian plus a linear baseline is fitted in time (linear power, as a scan's
// lines are: scan_fit.hpp); the width in seconds times the source's rate across the sky is the
// beamwidth, and the time of the peak against the moment the source passed where the station
// believed the beam pointed is the pointing error along the path. The rate and the path come
// from where the beam stood relative to the source at each reading (the ephemeris), so a star's
// 15.04°/h·cos δ and the Sun's or the Moon's own motion are all the same case.
//
// A drift measures nothing across the path: the offset is the error's component along it. Near
// the meridian a source's path runs along the azimuth, so a drift there measures the azimuth
// error alone (drift_az_offset_deg).

#include <cstddef>
#include <optional>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

/// Readings averaged over one interval of a drift.
struct DriftBin {
  double t_s = 0.0;    ///< mean time of its readings
  double power = 0.0;  ///< mean linear power (10^(dB/10))
  /// Mean place of the (believed) beam relative to the source, in the frame of the still beam
  /// (drift_scan.hpp): minus the source's offset from the beam.
  SkyOffset pointed;
  int readings = 0;
};

struct DriftFit {
  double peak_s = 0.0;      ///< when the power peaked
  double peak_std_s = 0.0;  ///< its standard error
  double width_s = 0.0;     ///< full width at half maximum, seconds
  double rate_deg_s = 0.0;  ///< the source's rate across the beam
  double width_deg = 0.0;   ///< width_s × rate: the beam convolved with the source
  double width_std_deg = 0.0;
  SkyOffset direction;            ///< unit vector: the beam's motion relative to the source
  double along_offset_deg = 0.0;  ///< the found offset's component along `direction`
  double along_std_deg = 0.0;
  double cross_track_deg = 0.0;  ///< the believed beam's closest approach across the path
  double peak_db = 0.0;          ///< the rise above the baseline, dB
  double noise_db = 0.0;         ///< rms of the residuals, dB
  double baseline = 0.0;         ///< linear, at the peak
  double slope_per_s = 0.0;      ///< the baseline's drift, linear per second
  double amplitude = 0.0;        ///< linear
  std::size_t used = 0;          ///< bins fitted

  /// The found offset (add it to the ephemeris to put the beam on the source, as a scan's peak):
  /// along_offset_deg along `direction`; nothing across.
  [[nodiscard]] SkyOffset offset() const {
    return {along_offset_deg * direction.xel_deg, along_offset_deg * direction.el_deg};
  }
};

/// The fewest bins a drift needs.
constexpr std::size_t kMinDriftBins = 15;

/// Fits `bins`; `beamwidth_deg` is the expected width (the start and the scale of the checks).
/// Refused when: fewer than kMinDriftBins bins; the source did not move across the beam; the fit
/// does not converge; the peak is not 5 noise rms above the baseline or lies outside the
/// recording; the width is below 0.3 or above 3 expected beamwidths.
Result<DriftFit> fit_drift(const std::vector<DriftBin>& bins, double beamwidth_deg);

/// A fixed source's rate across the sky: the sidereal rate 360°/86164.0905 s times cos δ
/// (astronomy-and-eme.md §8: 15.04″/s·cos δ).
double sidereal_drift_rate_deg_s(double dec_deg);

/// The mount's azimuth error a drift says, taking the elevation as right: the along-path offset
/// over the path's share of cross-elevation, over cos E. nullopt when the path runs within 60° of
/// the vertical (more elevation than azimuth: a drift there cannot say the azimuth).
std::optional<double> drift_az_offset_deg(const DriftFit& fit, double el_deg);

}  // namespace azt::calibration
