#include "config/receiver_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

ReceiverConfig receiver_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("receiver");
  ReceiverConfig c;
  const std::string source = s.text("source").value_or("none");  // one of the schema's choices
  if (source == "rtl_power") c.source = ReceiverConfig::Source::RtlPower;
  if (source == "udp") c.source = ReceiverConfig::Source::Udp;
  if (source == "sim") c.source = ReceiverConfig::Source::Sim;
  c.path = s.text("path").value_or("");
  if (c.source == ReceiverConfig::Source::RtlPower && (c.path.empty() || c.path.front() != '/')) {
    s.fail("path", "rtl_power needs the absolute path of the FIFO or file it writes");
  }
  c.bind = s.text("bind").value_or(c.bind);
  c.port = static_cast<unsigned short>(s.integer("port").value_or(0));
  if (c.source == ReceiverConfig::Source::Udp && c.port == 0) s.fail("port", "udp needs a port");
  c.stale_s = s.number("stale_s").value_or(c.stale_s);
  const ConfigSection station = file.section("station");
  c.dish.dish_m = station.number("dish_m");
  c.dish.efficiency = station.number("efficiency");
  c.dish.tsys_k = s.number("tsys_k");
  c.dish.bandwidth_hz = s.number("bandwidth_hz");
  c.dish.integration_s = s.number("integration_s").value_or(c.dish.integration_s);
  return c;
}

}  // namespace azt::app
