#pragma once
// "HOST:PORT" values of the configuration ([radio] rigctld, [wsjtx] listen): a host name or IPv4
// address and a port, or "[IPV6]:PORT".

#include <string>
#include <string_view>

namespace azt::app {

class ConfigSection;

struct HostPort {
  std::string host;
  unsigned short port = 0;
  [[nodiscard]] std::string text() const;
};

/// Throws UsageError naming `key` of `section` unless `text` is "HOST:PORT" or "[V6]:PORT" with
/// a port of 1 to 65535; `example` is quoted in the message.
HostPort parse_host_port(const ConfigSection& section, std::string_view key,
                         const std::string& text, std::string_view example);

}  // namespace azt::app
