#pragma once
// Which terms of the pointing model a set of scans determines (docs/calibration.md). TPOINT's
// practice (P. T. Wallace, TPOINT manual, "fit only what the data determine"): a term the scans
// cannot separate from the others is held at its prior value, and the fit says why. The terms
// are taken in a fixed order, the large terms of an amateur mount first: the encoder zeros (IA,
// IE), the mast's tilt (AN, AW), collimation (CA), sag, and the non-perpendicularity (NPAE, the
// smallest on most mounts and the first to go with little elevation spread). A term is taken when,
// given the terms taken before it, the scans still see it: the part of its column in the normal
// matrix the earlier terms do not explain (its Cholesky pivot) is a fair share of the whole, and
// scan noise would not move it far.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "azt/calibration/pointing_model.hpp"

namespace azt::calibration {

/// Which terms to fit, in PointingTerms's order (IA, IE, CA, NPAE, AN, AW, SAG).
using TermMask = std::array<bool, PointingTerms::kCount>;
constexpr TermMask kAllTerms{true, true, true, true, true, true, true};

/// The order terms are taken in, as indices into PointingTerms's order.
constexpr std::array<std::size_t, PointingTerms::kCount> kTermOrder{0, 1, 4, 5, 2, 6, 3};

/// "IA", "IE", "CA", "NPAE", "AN", "AW", "SAG".
const char* term_name(std::size_t index);
/// "ia_deg", "ie_deg", … (the [pointing] keys).
const char* term_key(std::size_t index);

struct SelectionLimits {
  /// A term that one degree of scan noise would move by more than this many degrees is not
  /// determined (10: 0.01° of noise moves it 0.1°).
  double max_sensitivity = 10.0;
  /// The least share of a term's column (squared length) the terms before it may leave
  /// unexplained: below, it is a combination of them (1e-4: its error a hundred times what it
  /// would be alone). Mostly the sensitivity decides; NPAE over 10–80° of elevation keeps only
  /// ~0.6 % of its column beside IA and CA and is still well fitted from forty scans.
  double min_independence = 1e-4;
};

/// Where the scans lie, for the reasons.
struct CoverageSpan {
  double min_el_deg = 0.0;
  double max_el_deg = 0.0;
  double az_arc_deg = 0.0;  ///< the smallest arc of azimuth holding every scan
};

struct TermSelection {
  TermMask fitted{};
  /// Why each held term is held; empty for a fitted one.
  std::array<std::string, PointingTerms::kCount> held;
};

/// Chooses the terms to fit. `normal` is JᵀJ of the scans' (relatively weighted) offsets in
/// degrees for all seven terms, 7×7 row-major; `requested` the terms the caller wants (the others
/// are "held by request"); `scans` how many scans' worth of offsets there are (n scans fit at
/// most n − 1 terms, one left for the scatter).
TermSelection select_terms(const std::vector<double>& normal, const TermMask& requested,
                           std::size_t scans, const CoverageSpan& span,
                           const SelectionLimits& limits = {});

/// The smallest arc of azimuth that holds every azimuth in `az_deg` (0 for none or one).
double azimuth_arc_deg(std::vector<double> az_deg);

}  // namespace azt::calibration
