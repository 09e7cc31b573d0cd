#pragma once
// The Moon's apparent libration and the echo spread it causes (docs/eme.md, WSJT-X's "Width"):
// as the Moon turns a little relative to the line of sight, its limbs approach and recede, and
// an echo is smeared over a band of frequencies. WSJT-X takes the change in a minute of the
// sub-observer point's selenographic longitude l and latitude b (lib/astro0.f90):
//   self:  width = 0.5 · 6741 · f_GHz · 2·√(dl² + db²)
//   DX:    width = 0.5 · 6741 · f_GHz · √((dl₁ + dl₂)² + (db₁ + db₂)²)
// with dl, db in degrees per minute (6741 ≈ 4·R_moon·1 GHz/c per degree a minute, in Hz). The
// Moon's orientation is the IAU WGCCRE model (Archinal et al. 2011, Celest. Mech. Dyn. Astron.
// 109: the Moon's pole and prime meridian with their 13 periodic terms), good to a few hundredths
// of a degree, far finer than a width needs.

#include "azt/astro/sky.hpp"

namespace azt::eme {

/// The sub-observer point: the selenographic longitude and latitude (degrees) of the point of
/// the Moon nearest the observer.
struct Libration {
  double lon_deg = 0.0;
  double lat_deg = 0.0;
};

/// The sub-observer point for the Moon seen at `moon` (apparent topocentric RA/Dec of date) at
/// Terrestrial Time `tt_jd` (Julian date). The equator of date is taken as the model's J2000
/// frame: the offset (precession, 0.35° by 2025) is constant over a minute and leaves the rates
/// unchanged to parts in 10⁵.
Libration apparent_libration(const astro::Place& moon, double tt_jd);

/// Self-echo width (Hz) from the sub-observer point now and a minute later.
double self_echo_width_hz(const Libration& now, const Libration& minute_later, double freq_mhz);

/// DX echo width (Hz): both stations' sub-observer points now and a minute later.
double dx_echo_width_hz(const Libration& own_now, const Libration& own_later,
                        const Libration& dx_now, const Libration& dx_later, double freq_mhz);

}  // namespace azt::eme
