#include "config/receiver_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

ReceiverConfig receiver_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("receiver", {"source", "path", "bind", "port", "stale_s"});
  ReceiverConfig c;
  const std::string source = s.text("source").value_or("none");
  if (source == "rtl_power") {
    c.source = ReceiverConfig::Source::RtlPower;
  } else if (source == "udp") {
    c.source = ReceiverConfig::Source::Udp;
  } else if (source == "sim") {
    c.source = ReceiverConfig::Source::Sim;
  } else if (source != "none") {
    s.fail("source", "must be \"none\", \"rtl_power\", \"udp\" or \"sim\"");
  }
  c.path = s.text("path").value_or("");
  if (c.source == ReceiverConfig::Source::RtlPower && (c.path.empty() || c.path.front() != '/')) {
    s.fail("path", "rtl_power needs the absolute path of the FIFO or file it writes");
  }
  c.bind = s.text("bind").value_or(c.bind);
  const auto port = s.integer("port").value_or(0);
  if (port < 0 || port > 65535) s.fail("port", "must be 1 to 65535");
  if (c.source == ReceiverConfig::Source::Udp && port == 0) s.fail("port", "udp needs a port");
  c.port = static_cast<unsigned short>(port);
  c.stale_s = s.number("stale_s").value_or(c.stale_s);
  if (!(c.stale_s >= 0.1 && c.stale_s <= 60.0)) s.fail("stale_s", "must be 0.1 to 60 seconds");
  return c;
}

}  // namespace azt::app
