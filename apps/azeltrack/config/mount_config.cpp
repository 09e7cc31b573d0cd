#include "config/mount_config.hpp"

#include <cmath>

#include "config/config_file.hpp"

namespace azt::app {
namespace {

/// The ranges are the schema's (config/schema_control_keys.cpp).
AxisMount read_axis(const ConfigSection& s, AxisMount a) {
  a.max_rate_deg_s = s.number("max_rate_deg_s").value_or(a.max_rate_deg_s);
  a.time_constant_s = s.number("time_constant_s").value_or(a.time_constant_s);
  a.min_duty = s.number("min_duty").value_or(a.min_duty);
  a.backlash_deg = s.number("backlash_deg").value_or(a.backlash_deg);
  a.encoder_bits = static_cast<std::uint8_t>(s.integer("encoder_bits").value_or(a.encoder_bits));
  return a;
}

PolMount read_pol(const ConfigSection& s) {
  PolMount p;
  p.axis = read_axis(s, p.axis);
  p.min_deg = s.number("min_deg").value_or(p.min_deg);
  p.max_deg = s.number("max_deg").value_or(p.max_deg);
  p.window_deg = s.number("window_deg").value_or(p.window_deg);
  return p;
}

}  // namespace

bool FixedElevation::in_beam(double target_el_deg) const {
  return std::abs(target_el_deg - el_deg) <= beam_width_deg / 2.0;
}

MountConfig mount_config_from(const ConfigFile& file) {
  const ConfigSection mount = file.section("mount");
  MountConfig m;
  m.az = read_axis(mount.child("az"), m.az);
  m.el = read_axis(mount.child("el"), m.el);
  if (const ConfigSection pol = mount.child("pol"); pol.present()) m.pol = read_pol(pol);
  const ConfigSection el = mount.child("el");
  if (const auto fixed = el.number("fixed_deg")) {
    m.el_fixed = FixedElevation{*fixed, el.number("beam_width_deg").value_or(20.0)};
  }
  return m;
}

}  // namespace azt::app
