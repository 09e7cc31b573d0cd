#include "config/host_port.hpp"

#include <algorithm>

#include "config/config_file.hpp"

namespace azt::app {

std::string HostPort::text() const {
  const bool v6 = host.find(':') != std::string::npos;
  return (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

HostPort parse_host_port(const ConfigSection& s, std::string_view key, const std::string& text,
                         std::string_view example) {
  const std::string usage = "must be \"HOST:PORT\" (for example \"" + std::string(example) + "\")";
  std::string host;
  std::string port;
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find("]:");
    if (close == std::string::npos) s.fail(key, usage);
    host = text.substr(1, close - 1);
    port = text.substr(close + 2);
  } else {
    if (std::count(text.begin(), text.end(), ':') != 1) s.fail(key, usage);
    const auto colon = text.find(':');
    host = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  const bool digits = !port.empty() && port.size() <= 5 &&
                      port.find_first_not_of("0123456789") == std::string::npos;
  if (host.empty() || !digits || std::stoul(port) == 0 || std::stoul(port) > 65535) {
    s.fail(key, usage);
  }
  return HostPort{host, static_cast<unsigned short>(std::stoul(port))};
}

}  // namespace azt::app
