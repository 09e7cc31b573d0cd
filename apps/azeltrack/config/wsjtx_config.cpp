#include "config/wsjtx_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

WsjtxConfig wsjtx_config_from(const ConfigFile& file) {
  const ConfigSection s = file.section("wsjtx");
  WsjtxConfig c;
  if (const auto text = s.text("listen"); text && !text->empty()) {
    c.listen = parse_host_port(s, "listen", *text, "127.0.0.1:2237");
  }
  c.follow_dx_grid = s.boolean("follow_dx_grid").value_or(true);
  c.hold_motion_while_transmitting = s.boolean("hold_motion_while_transmitting").value_or(true);
  c.move_in_last_s = s.number("move_in_last_s").value_or(0.0);
  return c;
}

}  // namespace azt::app
