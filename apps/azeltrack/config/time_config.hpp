#pragma once
// [time] (docs/time.md): how the daemon reads chrony, and whether the console may set chrony's
// upstream NTP servers (the seed's "NTP Client Server"). Time itself is chrony's job
// (packaging/chrony/azeltrack.conf); azeltrack watches it and says when it cannot be trusted.

#include <string>

namespace azt::app {

class ConfigFile;

struct TimeConfig {
  std::string chronyc = "chronyc";  ///< the program that asks chronyd
  std::string chrony_socket;      ///< chronyc -h (a command socket or host); "": chronyc's default
  double poll_s = 5.0;            ///< how often the clock is checked
  std::string rtc = "/dev/rtc0";  ///< the battery-backed clock whose presence is reported
  /// The console may write the upstream servers to `sources_file` and have chronyd reload them.
  bool manage_chrony = false;
  std::string sources_file = "/var/lib/azeltrack/chrony/azeltrack.sources";
};

/// Throws UsageError naming the key on any invalid value.
TimeConfig time_config_from(const ConfigFile& file);

}  // namespace azt::app
