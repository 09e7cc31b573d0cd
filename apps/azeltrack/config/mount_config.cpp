#include "config/mount_config.hpp"

#include "azt/util/format_number.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

/// Reads `key` into `value` when present; a value outside [lo, hi] is refused naming the key.
void read_range(const ConfigSection& s, const char* key, double lo, double hi, double& value) {
  const auto v = s.number(key);
  if (!v) return;
  if (!(*v >= lo && *v <= hi)) {
    s.fail(key, "must be " + format_number(lo) + " to " + format_number(hi));
  }
  value = *v;
}

AxisMount read_axis(const ConfigSection& s, AxisMount a) {
  if (!s.present()) return a;
  read_range(s, "max_rate_deg_s", 0.01, 90.0, a.max_rate_deg_s);
  read_range(s, "time_constant_s", 0.01, 10.0, a.time_constant_s);
  read_range(s, "min_duty", 0.0, 0.9, a.min_duty);
  read_range(s, "backlash_deg", 0.0, 5.0, a.backlash_deg);
  if (const auto bits = s.integer("encoder_bits")) {
    if (*bits < 9 || *bits > 16) s.fail("encoder_bits", "must be 9 to 16");
    a.encoder_bits = static_cast<std::uint8_t>(*bits);
  }
  return a;
}

}  // namespace

MountConfig mount_config_from(const ConfigFile& file) {
  const ConfigSection mount = file.section("mount", {"az", "el"});
  const std::initializer_list<std::string_view> keys = {
      "max_rate_deg_s", "encoder_bits", "time_constant_s", "min_duty", "backlash_deg"};
  MountConfig m;
  m.az = read_axis(mount.child("az", keys), m.az);
  m.el = read_axis(mount.child("el", keys), m.el);
  return m;
}

}  // namespace azt::app
