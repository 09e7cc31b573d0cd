#include "config/actuator_config.hpp"

#include <array>
#include <string>
#include <utility>

#include "config/config_file.hpp"
#include "config/hardware_config.hpp"

namespace azt::app {
namespace {

constexpr std::array<std::string_view, 5> kTriangleKeys{
    "actuator_pivot_to_fixed_mm", "actuator_pivot_to_moving_mm", "actuator_offset_deg",
    "actuator_retracted_mm", "actuator_extended_mm"};

}  // namespace

control::ActuatorGeometryConfig read_actuator(const ConfigSection& s, std::string_view needed_by) {
  control::ActuatorGeometryConfig g;
  const std::array<double*, 5> fields{&g.pivot_to_fixed_mm, &g.pivot_to_moving_mm, &g.offset_deg,
                                      &g.retracted_mm, &g.extended_mm};
  for (std::size_t i = 0; i < kTriangleKeys.size(); ++i) {
    const auto v = s.number(kTriangleKeys.at(i));
    if (!v) {
      s.fail(kTriangleKeys.at(i), "is needed by " + std::string(needed_by) +
                                      " (the actuator's triangle, docs/hardware.md)");
    }
    *fields.at(i) = *v;
  }
  g.sense = s.choice("actuator_extend", kActuatorSenses, control::ActuatorSense::ExtendRaises);
  if (auto ok = control::ActuatorGeometryConfig::make(g); !ok) {
    fail_field(s, "actuator_", ok.error().message);
  }
  if (auto ok = control::ActuatorGeometry::make(g); !ok) {
    fail_field(s, "actuator_", ok.error().message);
  }
  return g;
}

void refuse_actuator_keys(const ConfigSection& s) {
  for (std::string_view key : kTriangleKeys) {
    if (s.has(key)) {
      s.fail(key,
             "is for an actuator's length: sensor = \"pulses\" with counts_per_mm, or a pot with "
             "pot_calibration_mm");
    }
  }
}

}  // namespace azt::app
