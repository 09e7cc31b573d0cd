#pragma once

#include <nlohmann/json.hpp>

#include "azt/astro/sky.hpp"
#include "azt/astro/target.hpp"
#include "common/sky_setup.hpp"

namespace azt::app {

/// Everything `sky` and `watch` show about one target at one instant.
struct TargetReport {
  astro::Target target;
  astro::Observation observation;
  /// For the Moon: the DX station's range rate (km/s) and where it sees the Moon.
  std::optional<double> dx_range_rate_km_s;
  std::optional<astro::Place> dx_place;
};

/// The sky at one instant for one station: the shared frame, computed once for all targets.
class SkySnapshot {
 public:
  /// Throws UsageError when the instant is outside the ephemeris or the leap-second table.
  SkySnapshot(const astro::Ephemeris& ephemeris, const SkySettings& settings,
              const astro::UtcInstant& utc);

  [[nodiscard]] TargetReport observe(const astro::Target& target) const;
  [[nodiscard]] const astro::TimeScales& time() const { return epoch_.time; }

 private:
  const astro::Ephemeris& ephemeris_;
  const SkySettings& settings_;
  astro::Epoch epoch_;
  astro::Station station_;
  std::optional<astro::Station> dx_station_;
};

/// The `sky --json` object: az_deg, el_deg (refracted), el_geometric_deg, ra_deg, dec_deg,
/// distance_km, range_rate_km_s, and for the Moon echo figures (per band, at --freq-mhz, DX).
nlohmann::json report_json(const TargetReport& report, const SkySnapshot& snapshot,
                           const SkySettings& settings, const std::string& ephemeris_name);

}  // namespace azt::app
