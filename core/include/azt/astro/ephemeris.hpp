#pragma once

#include <string>

#include "azt/astro/time_scales.hpp"
#include "azt/astro/vec3.hpp"
#include "azt/util/result.hpp"

namespace azt::astro {

/// Where the Earth and the Sun are relative to the solar-system barycentre.
struct EarthSun {
  PosVel earth_bary;  ///< Earth's centre, BCRS
  PosVel sun_bary;    ///< Sun's centre, BCRS
};

/// A source of geometric (not light-time corrected, not aberrated) positions for the Sun, Earth
/// and Moon, ICRS axes, argument TT (used as TDB). The reduction to apparent topocentric places
/// (light time, aberration, precession-nutation, Earth rotation) lives in sky.hpp and is shared by
/// every backend, so that backends differ only in their ephemeris.
class Ephemeris {
 public:
  virtual ~Ephemeris() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual Result<EarthSun> earth_sun(const JulianDate& tt) const = 0;
  /// The Moon's centre relative to the Earth's centre (GCRS axes).
  [[nodiscard]] virtual Result<PosVel> moon_geocentric(const JulianDate& tt) const = 0;
};

}  // namespace azt::astro
