#pragma once
// [hooks] (docs/satellites.md "Hooks"): the programs the station runs at a scheduled pass's AOS
// and LOS, when it pre-positions for one and when it parks. Each is an argv, run without a shell.

#include <string>
#include <vector>

namespace azt::app {

class ConfigFile;

struct HooksConfig {
  /// Each: the program's absolute path, then its arguments; empty: no hook.
  std::vector<std::string> aos;
  std::vector<std::string> los;
  std::vector<std::string> pre_position;
  std::vector<std::string> park;
  double timeout_s = 30.0;  ///< then the hook's process group gets SIGTERM, SIGKILL 2 s later
};

/// Throws UsageError naming the key when a program is not an absolute path, or a value holds
/// a NUL character (it would cut the argument short).
HooksConfig hooks_config_from(const ConfigFile& file);

}  // namespace azt::app
