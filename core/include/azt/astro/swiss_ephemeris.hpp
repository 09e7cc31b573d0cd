#pragma once

#include <string>

#include "azt/astro/ephemeris.hpp"

namespace azt::astro {

/// Swiss Ephemeris (libswe, AGPL-3.0 or commercial) reading its compressed DE431-derived files
/// (`.se1`, Debian package swe-basic-data, 1800–2399 CE), ≈ 0.001″ from JPL. Built only when
/// libswe is found (CMake AZT_SWISS). libswe keeps process-wide state: use one instance, from one
/// thread.
class SwissEphemeris final : public Ephemeris {
 public:
  /// Checks that the data files are readable (libswe would otherwise silently fall back to its
  /// 3″ Moshier theory). `ephe_path` empty = libswe's default (/usr/share/libswe/ephe).
  static Result<SwissEphemeris> open(const std::string& ephe_path = {});

  [[nodiscard]] std::string name() const override { return "swiss"; }
  [[nodiscard]] Result<EarthSun> earth_sun(const JulianDate& tt) const override;
  [[nodiscard]] Result<PosVel> moon_geocentric(const JulianDate& tt) const override;

 private:
  SwissEphemeris() = default;
};

}  // namespace azt::astro
