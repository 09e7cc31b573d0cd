#pragma once
// The scan log of a pointing calibration (docs/calibration.md): every scan's result, kept so the
// model can be fitted from them, today's and earlier sessions' and other tools' alike. A row is
// one moment: where the source was on the sky, and how far the mount's angles (the encoders after
// their offset: the pointing model's frame) were from it while the beam was on it. A cross scan's
// two lines are measured minutes apart and each keeps its own moment (the source and the mount's
// error move meanwhile): two rows, each with the offset its line measured; a five-point scan or a
// raster is one row that measured both.
//
// The offsets are in the mount's frame, so a row holds whatever the station's corrections were
// when it was scanned; it stays true while the encoder offsets ([corrections] az_offset_deg,
// el_offset_deg) do not change (after such a change, start a new log).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/astro/time_scales.hpp"
#include "azt/calibration/pointing_fit.hpp"
#include "azt/calibration/scan_fit.hpp"
#include "azt/control/corrections.hpp"
#include "azt/control/modes.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

/// Which offsets a row measured.
enum class Measured {
  Both,  ///< both at this moment (five-point, raster, other tools)
  Az,    ///< the cross-elevation line's: daz counts, del is the scan's for reference
  El,    ///< the elevation line's
};

std::string_view to_string(Measured m);
/// "both", "az" or "el".
Result<Measured> parse_measured(std::string_view text);

struct ScanLogEntry {
  astro::UtcInstant utc;
  std::string source;
  double az_deg = 0.0;  ///< the source's apparent (refracted) azimuth at `utc`
  double el_deg = 0.0;
  double daz_deg = 0.0;  ///< mount azimuth − source azimuth with the beam on the source
  double del_deg = 0.0;  ///< mount elevation − source elevation
  Measured measured = Measured::Both;
  std::optional<double> sigma_xel_deg;  ///< the scan fit's standard errors, on the sky
  std::optional<double> sigma_el_deg;
  std::optional<double> snr_db;         ///< the peak against the fit's residual noise
  std::optional<double> rise_db;        ///< the peak over the baseline (the Y-factor)
  std::optional<double> beamwidth_deg;  ///< the fitted width, the source's size removed
  double weight = 1.0;                  ///< relative weight in the fit; 0 leaves it out
};

/// A scan the fit found, for the log.
struct FinishedScan {
  std::string source;
  ScanKind kind = ScanKind::Cross;
  ScanFit fit;
  control::AzEl sky_xel;  ///< the source when the cross-elevation line's readings centre
  control::AzEl sky_el;   ///< and when the elevation line's do
  astro::UtcInstant utc_xel;
  astro::UtcInstant utc_el;
  double source_size_deg = 0.0;
};

/// The mount's angles at which the beam was on the source at `sky`, from the offset a scan found:
/// the controller believed the beam at source + `peak`; undo the tilt table, the user correction
/// and the model that `in_use` applied to the reading (control/corrections.hpp's order).
control::AzEl mount_on_source(const control::PositionCorrections& in_use, const control::AzEl& sky,
                              const SkyOffset& peak);

/// The rows of a finished scan: two for a cross scan (one per line), one for the others.
std::vector<ScanLogEntry> log_entries(const FinishedScan& scan,
                                      const control::PositionCorrections& in_use);

/// The rows as the fit takes them: mount = source + (daz, del), each row's measured offsets, its
/// standard errors and weight.
std::vector<PointingObservation> observations_from_log(const std::vector<ScanLogEntry>& log);

}  // namespace azt::calibration
