#pragma once
// The spatial polarisation offset to the DX station on the Moon path now (Dpol, WSJT-X's
// Astronomical Data: eme/polarisation.hpp), for the daemon's polarisation axis. The same figure
// as the EME data's `dpol_deg` (sky_report.cpp) and `simulate`'s pol track, without the rest of
// the Moon's conditions: two Moon positions and two parallactic angles.

#include <optional>

#include "azt/astro/ephemeris.hpp"
#include "common/sky_setup.hpp"

namespace azt::app {

/// Dpol in degrees ((−90, 90]) at `unix_s`, or nullopt without a DX station in `settings` or
/// where the sky cannot be computed (outside the ephemeris or the leap-second table).
std::optional<double> moon_dpol_deg(const astro::Ephemeris& ephemeris, const SkySettings& settings,
                                    double unix_s);

}  // namespace azt::app
