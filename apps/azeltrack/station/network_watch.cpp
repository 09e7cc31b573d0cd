#include "station/network_watch.hpp"

#include <utility>

#include "azt/linux/networkmanager_wifi.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

template <typename T>
json optional_json(const std::optional<T>& v) {
  return v ? json(*v) : json(nullptr);
}

json interface_json(const linux_os::NetworkInterface& n) {
  json j{{"name", n.name},
         {"kind", linux_os::to_string(n.kind)},
         {"operstate", n.operstate},
         {"up", n.up},
         {"carrier", optional_json(n.carrier)},
         {"mac", optional_json(n.mac)},
         {"speed_mbps", optional_json(n.speed_mbps)},
         {"addresses", n.addresses},
         {"wifi", nullptr}};
  if (n.wifi) {
    j["wifi"] = {{"ssid", optional_json(n.wifi->ssid)},
                 {"signal_dbm", optional_json(n.wifi->signal_dbm)},
                 {"signal_percent", optional_json(n.wifi->signal_percent)}};
  }
  return j;
}

}  // namespace

NetworkReading read_network_reading(const linux_os::NetworkPaths& paths) {
  NetworkReading r{linux_os::read_network_interfaces(paths), false};
  const auto nm = linux_os::read_networkmanager_wifi();
  r.networkmanager = nm.has_value();
  if (!nm) return r;
  for (auto& n : r.interfaces) {
    const auto link = nm->find(n.name);
    if (!n.wifi || link == nm->end()) continue;
    n.wifi->ssid = link->second.ssid;
    // NetworkManager's strength is the access point's; the kernel's dBm, when known, stays.
    if (link->second.signal_percent) n.wifi->signal_percent = link->second.signal_percent;
  }
  return r;
}

NetworkWatch::NetworkWatch(boost::asio::io_context& io, NetworkWatchParts parts)
    : p_(std::move(parts)), looks_(io, p_.poll_s, p_.offload, p_.probe, [this](NetworkReading r) {
        on_reading(std::move(r));
      }) {
  looks_.start();
}

void NetworkWatch::check_now() { looks_.now(); }

void NetworkWatch::on_reading(NetworkReading reading) {
  for (const auto& n : reading.interfaces) {
    const auto before = logged_up_.find(n.name);
    if (before != logged_up_.end() && before->second == n.up) continue;
    if (before != logged_up_.end() || !n.up) {
      p_.log("network: " + n.name + " link " + (n.up ? "up" : "down") + " (" + n.operstate + ")");
    }
    logged_up_[n.name] = n.up;
  }
  latest_ = std::move(reading);
}

json NetworkWatch::to_json() const {
  json interfaces = json::array();
  if (!latest_) return {{"interfaces", interfaces}, {"networkmanager", false}};
  for (const auto& n : latest_->interfaces) interfaces.push_back(interface_json(n));
  return {{"interfaces", interfaces}, {"networkmanager", latest_->networkmanager}};
}

}  // namespace azt::app
