#pragma once

#include "azt/astro/ephemeris.hpp"

namespace azt::astro {

/// ERFA's analytical theories: eraEpv00 (Earth and Sun, VSOP2000-based, ≤ 0.015″ in the Sun's
/// direction 1900–2100) and eraMoon98 (Meeus' ELP-2000/82 truncation: 2.9″ RMS, 18″ worst in
/// direction, 6 km RMS in distance, 36 mm/s RMS in velocity 1950–2100). Always available.
class ErfaEphemeris final : public Ephemeris {
 public:
  [[nodiscard]] std::string name() const override { return "erfa"; }
  [[nodiscard]] Result<EarthSun> earth_sun(const JulianDate& tt) const override;
  [[nodiscard]] Result<PosVel> moon_geocentric(const JulianDate& tt) const override;
};

}  // namespace azt::astro
