#include "azt/linux/networkmanager_wifi.hpp"

#include <systemd/sd-bus.h>

#include <cstdint>
#include <type_traits>
#include <vector>

namespace azt::linux_os {
namespace {

// NetworkManager's D-Bus API (https://networkmanager.dev/docs/api/latest/spec.html).
constexpr const char* kService = "org.freedesktop.NetworkManager";
constexpr const char* kRoot = "/org/freedesktop/NetworkManager";
constexpr const char* kDevice = "org.freedesktop.NetworkManager.Device";
constexpr const char* kWireless = "org.freedesktop.NetworkManager.Device.Wireless";
constexpr const char* kAccessPoint = "org.freedesktop.NetworkManager.AccessPoint";
constexpr std::uint32_t kDeviceTypeWifi = 2;  // NM_DEVICE_TYPE_WIFI
constexpr std::uint64_t kCallTimeoutUs = 2'000'000;

struct Bus {
  sd_bus* bus = nullptr;
  Bus() = default;
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;
  ~Bus() { sd_bus_flush_close_unref(bus); }
};

struct Message {
  sd_bus_message* m = nullptr;
  Message() = default;
  Message(const Message&) = delete;
  Message& operator=(const Message&) = delete;
  ~Message() { sd_bus_message_unref(m); }
};

std::optional<std::vector<std::string>> device_paths(sd_bus* bus) {
  sd_bus_error error = SD_BUS_ERROR_NULL;
  Message reply;
  const int r =
      sd_bus_call_method(bus, kService, kRoot, kService, "GetDevices", &error, &reply.m, "");
  sd_bus_error_free(&error);
  if (r < 0 || sd_bus_message_enter_container(reply.m, 'a', "o") < 0) return std::nullopt;
  std::vector<std::string> paths;
  const char* path = nullptr;
  while (sd_bus_message_read(reply.m, "o", &path) > 0) paths.emplace_back(path);
  return paths;
}

/// A property of a plain type ("u", "y"), or a string ("s", "o") copied out before the reply
/// that holds it is freed.
template <typename T>
std::optional<T> property(sd_bus* bus, const std::string& path, const char* iface, const char* name,
                          const char* type) {
  sd_bus_error error = SD_BUS_ERROR_NULL;
  Message reply;
  const int r =
      sd_bus_get_property(bus, kService, path.c_str(), iface, name, &error, &reply.m, type);
  sd_bus_error_free(&error);
  if (r < 0) return std::nullopt;
  if constexpr (std::is_same_v<T, std::string>) {
    const char* text = nullptr;
    if (sd_bus_message_read(reply.m, type, &text) < 0 || text == nullptr) return std::nullopt;
    return std::string(text);
  } else {
    T value{};
    if (sd_bus_message_read(reply.m, type, &value) < 0) return std::nullopt;
    return value;
  }
}

std::optional<std::string> ssid_of(sd_bus* bus, const std::string& ap) {
  sd_bus_error error = SD_BUS_ERROR_NULL;
  Message reply;
  const int r =
      sd_bus_get_property(bus, kService, ap.c_str(), kAccessPoint, "Ssid", &error, &reply.m, "ay");
  sd_bus_error_free(&error);
  const void* bytes = nullptr;
  std::size_t size = 0;
  if (r < 0 || sd_bus_message_read_array(reply.m, 'y', &bytes, &size) < 0) return std::nullopt;
  return std::string(static_cast<const char*>(bytes), size);
}

WifiLink link_of(sd_bus* bus, const std::string& device) {
  WifiLink link;
  const auto ap = property<std::string>(bus, device, kWireless, "ActiveAccessPoint", "o");
  if (!ap || *ap == "/") return link;  // not associated
  const std::string& ap_path = *ap;
  link.ssid = ssid_of(bus, ap_path);
  if (const auto strength = property<std::uint8_t>(bus, ap_path, kAccessPoint, "Strength", "y")) {
    link.signal_percent = *strength;
  }
  return link;
}

}  // namespace

std::optional<std::map<std::string, WifiLink>> read_networkmanager_wifi() {
  Bus bus;
  if (sd_bus_open_system(&bus.bus) < 0) return std::nullopt;
  sd_bus_set_method_call_timeout(bus.bus, kCallTimeoutUs);
  const auto devices = device_paths(bus.bus);
  if (!devices) return std::nullopt;
  std::map<std::string, WifiLink> links;
  for (const auto& device : *devices) {
    if (property<std::uint32_t>(bus.bus, device, kDevice, "DeviceType", "u") != kDeviceTypeWifi) {
      continue;
    }
    const auto name = property<std::string>(bus.bus, device, kDevice, "Interface", "s");
    if (name) links[*name] = link_of(bus.bus, device);
  }
  return links;
}

}  // namespace azt::linux_os
