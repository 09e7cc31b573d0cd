#pragma once

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <vector>

#include "azt/astro/target.hpp"
#include "common/sky_setup.hpp"

namespace azt::app {

/// Where the station is and what it can point at: [station], [atmosphere], [sources] and the
/// band ([moon]); what `watch` reads (docs/configuration.md).
struct SkyConfig {
  SkySettings settings;
  std::string band_name;               ///< the band whose Moon echo Doppler is shown
  std::vector<astro::Target> targets;  ///< Sun, Moon, then the listed sources
};

class ConfigFile;

/// The station, sky and atmosphere tables of a parsed configuration file.
SkyConfig sky_config_from(const ConfigFile& file);

/// Reads and validates a TOML configuration file. Unknown keys, wrong types and out-of-range
/// values are errors naming the key; throws UsageError.
SkyConfig load_sky_config(const std::string& path);

/// A target of the station by name, case-blind: "sun", "moon", a source's name or alias, with or
/// without spaces ("casa", "Cassiopeia A").
std::optional<astro::Target> find_sky_target(const SkyConfig& sky, const std::string& name);

/// Makes the [station] table's position `lat_deg`, `lon_deg` (and `alt_m` when given); the grid
/// is then derived from it, so a `grid` key is removed.
void set_station_position(toml::table& station, double lat_deg, double lon_deg,
                          std::optional<double> alt_m);

}  // namespace azt::app
