#pragma once
// The sky at one instant for one station (and its DX partner): the frame is computed once and
// every target is observed in it, as `sky`, `watch`, the console's target list and the sky
// follower do every second.

#include <optional>

#include "azt/astro/ephemeris.hpp"
#include "azt/astro/observer.hpp"
#include "azt/astro/refraction.hpp"
#include "azt/astro/sky.hpp"
#include "azt/astro/target.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/util/result.hpp"

namespace azt::astro {

/// Where the station is, and what it needs to see a target as it appears there.
struct SkySite {
  Observer observer;
  std::optional<Observer> dx;  ///< a DX station, for DX echo Doppler
  Atmosphere atmosphere;       ///< for refraction
};

/// One target at one instant.
struct TargetReport {
  Target target;
  Observation observation;
  /// For the Moon with a DX station: its range rate (km/s) and where it sees the Moon.
  std::optional<double> dx_range_rate_km_s;
  std::optional<Place> dx_place;
};

class SkySnapshot {
 public:
  /// Fails when `time` is outside the ephemeris. `ephemeris` must outlive the snapshot.
  static Result<SkySnapshot> at(const Ephemeris& ephemeris, const SkySite& site,
                                const TimeScales& time);

  /// Fails for a target outside its table (a spacecraft's vectors) or the ephemeris.
  [[nodiscard]] Result<TargetReport> observe(const Target& target) const;
  [[nodiscard]] const TimeScales& time() const { return epoch_.time; }
  /// The same station `seconds` later (for rates: the Moon's libration over a minute). TAI−UTC
  /// and DUT1 are kept: a leap second inside the interval shifts it by a second at most.
  [[nodiscard]] Result<SkySnapshot> later(double seconds) const;

 private:
  SkySnapshot(const Ephemeris& ephemeris, const SkySite& site, const Epoch& epoch);

  const Ephemeris* ephemeris_;
  SkySite site_;
  Epoch epoch_;
  Station station_;
  std::optional<Station> dx_station_;
};

}  // namespace azt::astro
