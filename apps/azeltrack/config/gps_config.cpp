#include "config/gps_config.hpp"

#include <algorithm>

#include "config/config_file.hpp"

namespace azt::app {
namespace {

/// "HOST:PORT", "[V6ADDR]:PORT", or a host alone (gpsd's own port, 2947).
void parse_endpoint(const ConfigSection& s, const std::string& text, GpsConfig& c) {
  std::string host = text;
  std::string port = "2947";
  if (!text.empty() && text.front() == '[') {
    const auto close = text.find(']');
    if (close == std::string::npos) s.fail("gpsd", "an IPv6 address needs its closing ']'");
    host = text.substr(1, close - 1);
    if (close + 1 < text.size()) {
      if (text[close + 1] != ':') s.fail("gpsd", "must be \"[ADDRESS]:PORT\"");
      port = text.substr(close + 2);
    }
  } else if (std::count(text.begin(), text.end(), ':') == 1) {
    const auto colon = text.find(':');
    host = text.substr(0, colon);
    port = text.substr(colon + 1);
  }
  const bool digits = !port.empty() && port.size() <= 5 &&
                      port.find_first_not_of("0123456789") == std::string::npos;
  if (host.empty() || !digits || std::stoul(port) == 0 || std::stoul(port) > 65535) {
    s.fail("gpsd", "must be \"HOST:PORT\" (gpsd's default is \"127.0.0.1:2947\")");
  }
  c.host = host;
  c.port = port;
}

}  // namespace

GpsConfig gps_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("gps");
  GpsConfig c;
  c.enabled = s.boolean("enabled").value_or(false);
  if (const auto endpoint = s.text("gpsd")) parse_endpoint(s, *endpoint, c);
  c.use_position = s.boolean("use_position").value_or(false);
  c.survey.min_sats = static_cast<int>(s.integer("min_sats").value_or(4));
  c.survey.hold_s = s.number("hold_s").value_or(60.0);
  c.survey.jump_m = s.number("jump_m").value_or(100.0);
  return c;
}

}  // namespace azt::app
