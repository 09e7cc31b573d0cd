#pragma once
// [export] (docs/eme.md): files azeltrack writes for other programs. `azel_dat`: WSJT-X's
// azel.dat (eme/azel_dat.hpp), rewritten every second; "" (the default) writes none.
// `azel_dat_pol_line`: its optional fifth line.

#include <string>

namespace azt::app {

class ConfigFile;

struct ExportConfig {
  std::string azel_dat;            ///< absolute path, or "" for none
  bool azel_dat_pol_line = false;  ///< WSJT-X's optional fifth line (Dpol, MNR, …)
};

/// Throws UsageError naming the key on an invalid value.
ExportConfig export_config_from(const ConfigFile& file);

}  // namespace azt::app
