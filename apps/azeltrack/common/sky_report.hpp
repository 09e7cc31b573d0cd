#pragma once

#include <nlohmann/json.hpp>

#include <optional>

#include "azt/astro/sky_snapshot.hpp"
#include "azt/astro/target.hpp"
#include "azt/eme/moon_conditions.hpp"
#include "common/sky_setup.hpp"

namespace azt::app {

/// The station of `settings` as the sky engine sees it.
astro::SkySite sky_site(const SkySettings& settings);

/// The sky at `utc` for the station of `settings`: an error outside the ephemeris or the
/// leap-second table.
Result<astro::SkySnapshot> sky_snapshot(const astro::Ephemeris& ephemeris,
                                        const SkySettings& settings, const astro::UtcInstant& utc);

/// For the command line: as sky_snapshot() and SkySnapshot::observe(), throwing UsageError.
astro::SkySnapshot sky_snapshot_or_throw(const astro::Ephemeris& ephemeris,
                                         const SkySettings& settings, const astro::UtcInstant& utc);
astro::TargetReport observe_or_throw(const astro::SkySnapshot& snapshot,
                                     const astro::Target& target);

/// WSJT-X's Astronomical Data for the Moon of `moon` (docs/eme.md), at the station's band (144 MHz
/// when none): nothing when the Sun cannot be observed at that instant.
std::optional<eme::MoonConditions> moon_conditions_at(const astro::TargetReport& moon,
                                                      const astro::SkySnapshot& snapshot,
                                                      const SkySettings& settings);

/// The `sky --json` object: az_deg, el_deg (refracted), el_geometric_deg, ra_deg, dec_deg,
/// distance_km, range_rate_km_s, and for the Moon echo figures (per band, at --freq-mhz, DX, and
/// their change per minute) and the EME conditions (Dpol, MNR, Tsky, Dgrd, Sun separation,
/// illumination); with a DX station the Moon seen from there (`dx`: az, el, Dec).
nlohmann::json report_json(const astro::TargetReport& report, const astro::SkySnapshot& snapshot,
                           const SkySettings& settings, const std::string& ephemeris_name);

}  // namespace azt::app
