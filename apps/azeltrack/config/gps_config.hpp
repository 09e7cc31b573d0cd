#pragma once
// [gps] (docs/gps.md): the receiver through gpsd, and whether the station's position comes from
// it. The station's position in use stays [station] in the file: a surveyed position is saved
// there (atomically, like every save), so a restart without GPS keeps it.

#include <string>

#include "azt/gnss/site_survey.hpp"

namespace azt::app {

class ConfigFile;

struct GpsConfig {
  bool enabled = false;
  std::string host = "127.0.0.1";  ///< [gps] gpsd = "HOST:PORT"
  std::string port = "2947";
  bool use_position = false;  ///< adopt the surveyed position as the station's
  /// min_sats, hold_s (how long a 3D fix must hold before its average is used), jump_m.
  gnss::SiteSurveySettings survey;
};

/// Throws UsageError naming the key on any invalid value.
GpsConfig gps_config_from(const ConfigFile& file);

}  // namespace azt::app
