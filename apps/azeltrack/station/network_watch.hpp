#pragma once
// The station's network links (docs/network.md), for the console's Ethernet and WiFi icons and its
// Network page: every few seconds the interfaces are read off the loop (sysfs, getifaddrs,
// /proc/net/wireless, and NetworkManager over D-Bus for the SSID where it runs); a link that
// goes up or down is logged once.

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/linux/asio.hpp"
#include "azt/linux/network_interfaces.hpp"
#include "common/off_loop.hpp"
#include "common/periodic_look.hpp"

namespace azt::app {

/// One look at the links.
struct NetworkReading {
  std::vector<linux_os::NetworkInterface> interfaces;
  bool networkmanager = false;  ///< NetworkManager answered on the system bus
};

struct NetworkWatchParts {
  double poll_s = 5.0;
  Offload offload;
  std::function<NetworkReading()> probe;  ///< on the worker (read_network_reading in the daemon)
  std::function<void(const std::string&)> log;
};

/// The links as the daemon reads them: sysfs and friends, with NetworkManager's SSIDs merged in.
NetworkReading read_network_reading(const linux_os::NetworkPaths& paths = {});

class NetworkWatch {
 public:
  /// Looks at once, then every poll_s.
  NetworkWatch(boost::asio::io_context& io, NetworkWatchParts parts);

  /// The console's `network`: {interfaces: [...], networkmanager} (docs/web-api.md).
  [[nodiscard]] nlohmann::json to_json() const;
  void check_now();

 private:
  void on_reading(NetworkReading reading);

  NetworkWatchParts p_;
  PeriodicLook<NetworkReading> looks_;
  std::optional<NetworkReading> latest_;
  std::map<std::string, bool> logged_up_;  ///< each interface's link as last logged
};

}  // namespace azt::app
