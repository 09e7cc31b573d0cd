#include "azt/linux/network_interfaces.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>
#include <netinet/in.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace azt::linux_os {
namespace {

namespace fs = std::filesystem;

constexpr int kArphrdLoopback = 772;  // <linux/if_arp.h> ARPHRD_LOOPBACK
constexpr int kArphrdEther = 1;       // ARPHRD_ETHER

/// The first line of a sysfs attribute; none when it cannot be read (some refuse while down).
std::optional<std::string> attribute(const fs::path& dir, const char* name) {
  std::ifstream in(dir / name);
  std::string line;
  if (!in || !std::getline(in, line)) return std::nullopt;
  return line;
}

std::optional<int> int_attribute(const fs::path& dir, const char* name) {
  const auto text = attribute(dir, name);
  if (!text) return std::nullopt;
  try {
    return std::stoi(*text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

/// WiFi has a `wireless` (or `phy80211`) entry; an Ethernet port is an Ethernet-type interface
/// with a `device` (a bridge, a veth or an ifb has none: it is "other").
LinkKind kind_of(const fs::path& dir, int type) {
  std::error_code ec;
  if (fs::exists(dir / "wireless", ec) || fs::exists(dir / "phy80211", ec)) return LinkKind::Wifi;
  return type == kArphrdEther && fs::exists(dir / "device", ec) ? LinkKind::Ethernet
                                                                : LinkKind::Other;
}

/// /proc/net/wireless: "  wlan0: 0000   54.  -56.  -256   0 0 0 0 0 0" (level in dBm).
std::map<std::string, double> wireless_levels(const std::string& path) {
  std::map<std::string, double> levels;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string name = line.substr(0, colon);
    name.erase(0, name.find_first_not_of(' '));
    std::istringstream fields(line.substr(colon + 1));
    std::string status;
    std::string link;
    std::string level;
    if (!(fields >> status >> link >> level)) continue;
    try {
      const double dbm = std::stod(level);  // "-56." parses; a header line does not
      if (std::isfinite(dbm) && dbm < 0.0) levels[name] = dbm;
    } catch (const std::exception&) {
    }
  }
  return levels;
}

std::string address_text(const sockaddr* addr, const sockaddr* mask) {
  std::array<char, INET6_ADDRSTRLEN> text{};
  int prefix = 0;
  if (addr->sa_family == AF_INET) {
    const auto* a = reinterpret_cast<const sockaddr_in*>(addr);  // NOLINT: the BSD socket API
    ::inet_ntop(AF_INET, &a->sin_addr, text.data(), text.size());
    if (mask != nullptr) {
      const auto* m = reinterpret_cast<const sockaddr_in*>(mask);  // NOLINT
      prefix = __builtin_popcount(m->sin_addr.s_addr);
    }
  } else {
    const auto* a = reinterpret_cast<const sockaddr_in6*>(addr);  // NOLINT
    ::inet_ntop(AF_INET6, &a->sin6_addr, text.data(), text.size());
    if (mask != nullptr) {
      const auto* m = reinterpret_cast<const sockaddr_in6*>(mask);  // NOLINT
      for (const unsigned char byte : m->sin6_addr.s6_addr) prefix += __builtin_popcount(byte);
    }
  }
  return std::string(text.data()) + "/" + std::to_string(prefix);
}

std::map<std::string, std::vector<std::string>> addresses_by_name() {
  std::map<std::string, std::vector<std::string>> out;
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) != 0) return out;
  for (const ifaddrs* i = list; i != nullptr; i = i->ifa_next) {
    if (i->ifa_addr == nullptr) continue;
    const int family = i->ifa_addr->sa_family;
    if (family != AF_INET && family != AF_INET6) continue;
    out[i->ifa_name].push_back(address_text(i->ifa_addr, i->ifa_netmask));
  }
  ::freeifaddrs(list);
  return out;
}

NetworkInterface read_one(const fs::path& dir) {
  NetworkInterface n;
  n.name = dir.filename().string();
  n.kind = kind_of(dir, int_attribute(dir, "type").value_or(0));
  n.operstate = attribute(dir, "operstate").value_or("unknown");
  if (const auto carrier = int_attribute(dir, "carrier")) n.carrier = *carrier == 1;
  n.up = n.operstate == "up" || (n.operstate == "unknown" && n.carrier == true);
  n.mac = attribute(dir, "address");
  if (n.mac && n.mac->empty()) n.mac.reset();
  const auto speed = int_attribute(dir, "speed");
  if (speed && *speed > 0) n.speed_mbps = speed;  // -1 when the link is down or unknown
  if (n.kind == LinkKind::Wifi) n.wifi = WifiLink{};
  return n;
}

}  // namespace

const char* to_string(LinkKind kind) {
  switch (kind) {
    case LinkKind::Ethernet:
      return "ethernet";
    case LinkKind::Wifi:
      return "wifi";
    case LinkKind::Other:
      return "other";
  }
  return "other";
}

int signal_percent_from_dbm(double dbm) {
  return static_cast<int>(std::clamp(std::lround(2.0 * (dbm + 100.0)), 0L, 100L));
}

std::vector<NetworkInterface> read_network_interfaces(const NetworkPaths& paths) {
  std::vector<NetworkInterface> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(paths.sysfs_net, ec)) {
    if (int_attribute(entry.path(), "type") == kArphrdLoopback) continue;
    out.push_back(read_one(entry.path()));
  }
  const auto levels = wireless_levels(paths.proc_wireless);
  auto addresses = addresses_by_name();
  for (auto& n : out) {
    n.addresses = std::move(addresses[n.name]);
    const auto level = levels.find(n.name);
    if (n.wifi && level != levels.end()) {
      n.wifi->signal_dbm = level->second;
      n.wifi->signal_percent = signal_percent_from_dbm(level->second);
    }
  }
  std::sort(out.begin(), out.end(),
            [](const NetworkInterface& a, const NetworkInterface& b) { return a.name < b.name; });
  return out;
}

}  // namespace azt::linux_os
