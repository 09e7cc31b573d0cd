#pragma once

#include <string>
#include <vector>

#include "azt/astro/ephemeris.hpp"

namespace azt::astro {

/// Another Ephemeris sampled at regular TT nodes and interpolated between them by cubic Hermite
/// polynomials on position and velocity — how JPL and Swiss Ephemeris files work, applied to
/// ERFA's analytical series, whose evaluation (eraEpv00: 20 µs) dominates a pointing otherwise.
/// With the default 10-minute step the table follows ERFA to 0.2 m and 5 mm/s for the Moon (1 cm
/// and 20 µm/s for the Earth and Sun): the limit is eraMoon98's own velocity series, which differs
/// from the derivative of its position by ~5 mm/s — a seventh of its stated 36 mm/s RMS accuracy.
/// In a pointing that is < 0.001″ and < 0.01 mm/s (tests/unit/tabulated_ephemeris_test.cpp).
/// Immutable once built: a tracker builds one for the day ahead and replaces it, no hidden cache.
class TabulatedEphemeris final : public Ephemeris {
 public:
  static constexpr double kDefaultStepDays = 10.0 / 1440.0;

  /// Samples `source` on [start, start + span_days] every `step_days`. Errors: a span or step
  /// that is not positive and finite, more than 100 000 nodes, or any failure of the source.
  static Result<TabulatedEphemeris> build(const Ephemeris& source, const JulianDate& start_tt,
                                          double span_days, double step_days = kDefaultStepDays);

  /// The source's name: the table changes cost, not the theory.
  [[nodiscard]] std::string name() const override { return name_; }
  /// Errors outside the tabulated span.
  [[nodiscard]] Result<EarthSun> earth_sun(const JulianDate& tt) const override;
  [[nodiscard]] Result<PosVel> moon_geocentric(const JulianDate& tt) const override;

  [[nodiscard]] bool covers(const JulianDate& tt) const;

 private:
  struct Node {
    PosVel earth;
    PosVel sun;
    PosVel moon;
  };
  struct Where {
    std::size_t index;
    double fraction;
  };

  TabulatedEphemeris() = default;
  [[nodiscard]] Result<Where> locate(const JulianDate& tt) const;

  std::string name_;
  JulianDate start_;
  double step_days_ = kDefaultStepDays;
  std::vector<Node> nodes_;
};

}  // namespace azt::astro
