#pragma once
// Common Moon windows (docs/eme.md): every interval in which two stations both see the Moon
// above their elevation limits and horizon masks, with the best minute's conditions (the highest
// Dgrd) and the Sun's separation. The Moon is sampled every `step_s` (10 min: the Moon's
// elevation moves ≤ 2.5° in that time, so no window longer than a step is missed) and each edge
// is found by bisection to within a second. A fixed-elevation array's band (max_el_deg) is
// sampled at least every 120 s per degree of its width: the Moon's elevation changes at most
// 0.25°/min, so it spends at least twice that long crossing the band.

#include <optional>
#include <vector>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/leap_seconds.hpp"
#include "azt/astro/observer.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/util/result.hpp"

namespace azt::eme {

struct MoonWindowSettings {
  double from_unix_s = 0.0;
  double days = 30.0;
  double min_el_deg = 0.0;  ///< the own station's limit (the Moon's centre, airless)
  /// The own station's upper limit: a fixed-elevation array sees the Moon only inside its
  /// vertical beam (fixed_deg ± beam width / 2, with min_el_deg the lower edge).
  std::optional<double> max_el_deg;
  double dx_min_el_deg = 0.0;  ///< the DX station's
  orbit::HorizonMask mask;     ///< the own station's horizon (flat 0° by default)
  orbit::HorizonMask dx_mask;
  double freq_mhz = 144.0;  ///< for Tsky and Dgrd
  double dut1_s = 0.0;
  double step_s = 600.0;
};

struct MoonWindow {
  double start_unix_s = 0.0;  ///< both see it (or the search's start, if already so)
  double end_unix_s = 0.0;    ///< one loses it (or the search's end)
  double best_unix_s = 0.0;   ///< the minute with the highest Dgrd
  double dgrd_db = 0.0;       ///< at the best minute
  double tsky_k = 0.0;
  double dpol_deg = 0.0;  ///< between the stations
  double sun_sep_deg = 0.0;
  double el_deg = 0.0;  ///< the own station's elevation at the best minute
  double dx_el_deg = 0.0;
};

/// `s` for an array fixed at `fixed_el_deg` whose vertical half-power beam is `beam_width_deg`
/// wide: the Moon counts only within half of it above or below (never below min_el_deg).
MoonWindowSettings in_fixed_beam(MoonWindowSettings s, double fixed_el_deg, double beam_width_deg);

/// The windows from `from_unix_s` for `days` days; an error outside the ephemeris or the
/// leap-second table.
Result<std::vector<MoonWindow>> moon_windows(const astro::Ephemeris& ephemeris,
                                             const astro::Observer& own, const astro::Observer& dx,
                                             const MoonWindowSettings& settings,
                                             const astro::LeapSecondTable& leap_seconds);

}  // namespace azt::eme
