#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace azt::astro {

/// A fixed radio source (ICRS/J2000 position, no proper motion: all are extragalactic or
/// galactic nebulae whose proper motion is far below a beamwidth).
struct RadioSource {
  std::string_view key;           ///< lower-case name used on the command line ("casa")
  std::string_view name;          ///< display name ("Cassiopeia A")
  std::string_view aliases;       ///< comma-separated lower-case alternatives ("cassiopeia,3c461")
  double ra_deg = 0.0;            ///< ICRS right ascension
  double dec_deg = 0.0;           ///< ICRS declination
  std::string_view kind;          ///< what it is and its angular size
  std::string_view position_ref;  ///< where the position comes from
  /// Flux density (Jy) at 1296, 2304 and 10368 MHz where a published fit covers it (or a
  /// flagged extrapolation), else nullopt.
  std::optional<double> flux_1296_jy;
  std::optional<double> flux_2304_jy;
  std::optional<double> flux_10368_jy;
  std::string_view flux_ref;
};

/// Every source in the built-in catalogue, in display order.
std::span<const RadioSource> radio_sources();

/// Finds a source by key, display name or alias (case-insensitive, spaces/underscores ignored).
const RadioSource* find_radio_source(std::string_view name);

}  // namespace azt::astro
