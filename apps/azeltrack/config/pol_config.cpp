#include "config/pol_config.hpp"

#include "config/config_file.hpp"
#include "config/daemon_config.hpp"

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

/// [mount.pol] on a backend that cannot drive it is refused rather than ignored: the operator
/// would otherwise believe the feed follows (docs/eme.md, "Polarisation axis").
void check_pol_backend(const ConfigFile& file, const DaemonConfig& c) {
  const ConfigSection antenna = file.section("antenna");
  if (c.hardware.pol && !c.mount.pol) {
    file.fail("[hardware.pol] drives the axis of [mount.pol], which the file does not have");
  }
  if ((c.gpio.pol_ccw_limit || c.gpio.pol_cw_limit) && !c.mount.pol) {
    file.fail(
        "[gpio] pol_ccw_limit / pol_cw_limit are the switches of [mount.pol]'s axis, "
        "which the file does not have");
  }
  if (!c.mount.pol) return;
  switch (c.backend) {
    case BackendKind::Sim:
      return;
    case BackendKind::Hardware:
      if (c.hardware.pol) return;
      antenna.fail("backend",
                   "is \"hardware\" with [mount.pol]: give the pol axis's drive and "
                   "sensor in [hardware.pol]");
    case BackendKind::Pwm:
      antenna.fail("backend",
                   "is \"pwm\" (azimuth and elevation only) with [mount.pol]: use "
                   "backend = \"hardware\" with [hardware.pol]");
    case BackendKind::Hamlib:
      antenna.fail("backend",
                   "is \"hamlib\", which has no polarisation axis, with [mount.pol]: "
                   "remove [mount.pol] or use backend = \"hardware\"");
  }
}

}  // namespace azt::app
