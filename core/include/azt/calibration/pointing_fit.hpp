#pragma once
// The pointing model fitted to scans of several sources across the sky (docs/calibration.md): each
// scan says at which mount angles the beam was on a source whose sky position the ephemeris gives;
// the terms are chosen to minimise the beam's residual offsets (cross-elevation and elevation,
// degrees on the sky). TPOINT's practice: fit only the terms the data determine, hold the others
// at their prior values and say why (term_selection.hpp).

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "azt/calibration/term_selection.hpp"
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
  /// Relative weight in χ² (the operator's: 0 leaves the scan out, its residual still shown).
  double weight = 1.0;
};

struct FitOptions {
  TermMask fit = kAllTerms;  ///< the terms wanted; the others are held at `start`'s values
  SelectionLimits limits;
  /// Fewer scans are refused: IA and IE, and one more to measure the scatter.
  std::size_t min_scans = 3;
};

/// One observation's offsets from its source on the sky (beam minus source), with the prior
/// terms and with the fitted ones.
struct ObservationResidual {
  SkyOffset before;
  SkyOffset after;
  bool used = true;  ///< counted in the fit (weight above 0, something measured)
};

struct PointingFit {
  PointingTerms terms;
  PointingTerms std_errors;  ///< one standard error per fitted term (0 for held terms)
  /// Why each held term was held at its prior value; empty for a fitted term.
  std::array<std::string, PointingTerms::kCount> held;
  double rms_before_deg = 0.0;  ///< the used observations' offsets on the sky with `start`
  double rms_deg = 0.0;         ///< and with the fitted terms
  double max_deg = 0.0;
  std::size_t observations = 0;                ///< scans' worth used (a scan measures two offsets)
  std::vector<ObservationResidual> residuals;  ///< one per observation, in order
};

/// Fits the terms the observations determine and holds the others (each with its reason).
/// Fails with the reason when there are fewer than `min_scans` scans' worth of offsets, when no
/// term can be fitted, when the fit does not converge, or a term comes out beyond ±10°.
Result<PointingFit> fit_pointing_model(const std::vector<PointingObservation>& observations,
                                       const PointingTerms& start = {},
                                       const FitOptions& options = {});

}  // namespace azt::calibration
