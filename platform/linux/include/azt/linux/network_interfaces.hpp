#pragma once
// The station's network links (docs/network.md), as the seed's Ethernet and WiFi icons show them:
// each interface's kind, link state, addresses and, for WiFi, the signal. Read from sysfs
// (/sys/class/net: operstate, carrier, address, speed, type, wireless), getifaddrs(3) for the
// addresses and /proc/net/wireless for the signal. The SSID is not in any of these: it comes
// from NetworkManager (networkmanager_wifi.hpp) where that runs. Plain file reads and one
// syscall, but run off the loop with the other looks at the system.

#include <optional>
#include <string>
#include <vector>

namespace azt::linux_os {

enum class LinkKind { Ethernet, Wifi, Other };

/// "ethernet", "wifi", "other".
const char* to_string(LinkKind kind);

struct WifiLink {
  std::optional<std::string> ssid;
  std::optional<double> signal_dbm;
  std::optional<int> signal_percent;  ///< 0..100
};

struct NetworkInterface {
  std::string name;
  LinkKind kind = LinkKind::Other;
  std::string operstate;        ///< the kernel's word: "up", "down", "dormant", "unknown", …
  bool up = false;              ///< operstate up (or unknown with a carrier, as tun devices say)
  std::optional<bool> carrier;  ///< none while the interface is administratively down
  std::optional<std::string> mac;
  std::optional<int> speed_mbps;       ///< none when the driver does not say (WiFi, virtual)
  std::vector<std::string> addresses;  ///< "192.168.1.5/24", "fe80::1/64"
  std::optional<WifiLink> wifi;        ///< WiFi interfaces only
};

struct NetworkPaths {
  std::string sysfs_net = "/sys/class/net";
  std::string proc_wireless = "/proc/net/wireless";
};

/// Every interface but loopback, by name; addresses from getifaddrs for the names found.
std::vector<NetworkInterface> read_network_interfaces(const NetworkPaths& paths = {});

/// NetworkManager's mapping of a signal in dBm to a percentage: 2 × (dBm + 100), 0..100.
int signal_percent_from_dbm(double dbm);

}  // namespace azt::linux_os
