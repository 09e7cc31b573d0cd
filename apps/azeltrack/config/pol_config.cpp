#include "config/pol_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

control::PolSettings pol_settings_from(const ConfigFile& file) {
  const ConfigSection s = file.section("pol");
  control::PolSettings p;
  // The schema has refused a name that is not a mode (config/schema_control_keys.cpp).
  if (const auto mode = s.text("mode")) {
    auto parsed = control::parse_pol_mode(*mode);
    if (!parsed) s.fail("mode", parsed.error().message);
    p.mode = *parsed;
  }
  p.fixed_deg = s.number("fixed_deg").value_or(p.fixed_deg);
  p.self_offset_deg = s.number("self_offset_deg").value_or(p.self_offset_deg);
  p.dx_offset_deg = s.number("dx_offset_deg").value_or(p.dx_offset_deg);
  p.hold_while_keyed = s.boolean("hold_while_keyed").value_or(p.hold_while_keyed);
  return p;
}

}  // namespace azt::app
