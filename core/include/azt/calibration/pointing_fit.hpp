#pragma once
// The pointing model fitted to scans of several sources across the sky (docs/calibration.md): each
// scan says at which mount angles the beam was on a source whose sky position the ephemeris gives;
// the terms are chosen to minimise the beam's residual offsets (cross-elevation and elevation,
// degrees on the sky). TPOINT's practice: fit only the terms the data determine.

#include <array>
#include <cstddef>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "azt/control/modes.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

/// One scan's result: the mount angles (after the encoder offset) at which the beam was on the
/// source, and where the source was on the sky at that moment. A scan whose two lines were
/// measured minutes apart gives one observation per line, each with the moment of its own line
/// and only the offset that line measured (the source, and the mount's error, move meanwhile).
struct PointingObservation {
  control::AzEl mount;
  control::AzEl sky;
  bool has_xel = true;  ///< the cross-elevation offset was measured at this moment
  bool has_el = true;   ///< the elevation offset was
  /// The scan fit's standard error of each offset. When every measured offset has one, the fit
  /// weights each by it (a Sun scan at 25 dB places the beam far better than Taurus A at 1 dB);
  /// otherwise all count alike.
  SkyOffset sigma;
};

/// Which terms to fit, in PointingTerms's order (IA, IE, CA, NPAE, AN, AW, SAG); the others are
/// held at `start`'s values.
using TermMask = std::array<bool, PointingTerms::kCount>;
constexpr TermMask kAllTerms{true, true, true, true, true, true, true};

struct PointingFit {
  PointingTerms terms;
  PointingTerms std_errors;     ///< one standard error per fitted term (0 for held terms)
  double rms_before_deg = 0.0;  ///< the observations' offsets on the sky with `start`
  double rms_deg = 0.0;         ///< and with the fitted terms
  double max_deg = 0.0;
  std::size_t observations = 0;
};

/// Fails with the reason when there are fewer measured offsets than twice the fitted terms plus
/// two (a scan measures two), when
/// the sky coverage cannot separate the terms (a singular fit: e.g. all sources at one
/// elevation cannot tell CA from IA), or a term comes out beyond ±10°.
Result<PointingFit> fit_pointing_model(const std::vector<PointingObservation>& observations,
                                       const PointingTerms& start = {},
                                       const TermMask& fit = kAllTerms);

}  // namespace azt::calibration
