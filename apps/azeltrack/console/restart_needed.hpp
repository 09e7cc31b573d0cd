#pragma once
// Which saved settings the running daemon does not run with yet: the keys applied at the next
// start (the schema's Applies::Restart) whose value in the file differs from the one it started
// with. Keys the console applies at once are never listed: every save of one goes through its
// apply path (settings_change.hpp), the GPS survey's position included. Secrets are not listed.

#include <toml++/toml.h>

#include <string>
#include <vector>

namespace azt::app {

/// "control.window_deg", "serial.2.baud": as `azeltrack config get|set` names them, in the
/// schema's order. An absent key counts as its default, and 1 and 1.0 as the same number.
std::vector<std::string> restart_needed(const toml::table& started, const toml::table& saved);

}  // namespace azt::app
