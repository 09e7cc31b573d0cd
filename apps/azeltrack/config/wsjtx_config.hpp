#pragma once
// [wsjtx] (docs/radio.md): listening to WSJT-X's UDP messages (its "UDP Server" setting).

#include <optional>

#include "config/host_port.hpp"

namespace azt::app {

class ConfigFile;

struct WsjtxConfig {
  std::optional<HostPort> listen;  ///< none: not listening; a multicast group is joined
  bool follow_dx_grid = true;      ///< WSJT-X's DX grid becomes the running DX (not saved)
  bool hold_motion_while_transmitting = true;
  double move_in_last_s = 0.0;  ///< move only in the last seconds of each period; 0: off
};

/// Throws UsageError naming the key on any invalid value.
WsjtxConfig wsjtx_config_from(const ConfigFile& file);

}  // namespace azt::app
