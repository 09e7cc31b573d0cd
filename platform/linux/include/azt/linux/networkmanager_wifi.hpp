#pragma once
// The SSID and signal of each WiFi link from NetworkManager over the system D-Bus
// (docs/network.md), where NetworkManager runs (Raspberry Pi OS and Debian desktops do; a minimal
// Debian with ifupdown does not, and then the SSID is simply not known). sd-bus from libsystemd,
// each call bounded to 2 s; it blocks for that long at worst, so it runs off the event loop.

#include <map>
#include <optional>
#include <string>

#include "azt/linux/network_interfaces.hpp"

namespace azt::linux_os {

/// Each WiFi device's link by interface name (ssid and signal_percent set while associated);
/// nullopt when NetworkManager is not on the system bus (or no system bus answers).
std::optional<std::map<std::string, WifiLink>> read_networkmanager_wifi();

}  // namespace azt::linux_os
