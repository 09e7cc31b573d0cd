#include "config/sim_actuator_config.hpp"

#include "config/config_file.hpp"
#include "config/hardware_config.hpp"
#include "config/pulse_sensor_config.hpp"

namespace azt::app {

std::optional<sim::SimActuatorElevation> sim_actuator_from(const ConfigFile& file,
                                                           const sim::AxisParams& el) {
  const ConfigSection hw = file.section("hardware").child("el");
  if (hw.text("sensor").value_or("") != "pulses") return std::nullopt;
  HardwareAxisConfig a = default_axis("el");
  a.sensor = AxisSensorKind::Pulses;
  read_pulse_sensor(hw, a, "gpiochip0");  // the lines are not used: only their number
  const control::PulseAxisConfig& pulses = *a.pulses;
  // The simulated actuator has a reed: a count in degrees or a quadrature pair is not flown (the
  // elevation is then the plain plant, read through the hub, as for any other sensor).
  if (!pulses.geometry || a.pulse_lines.size() != 1) return std::nullopt;
  const ConfigSection s = file.section("sim").child("el");
  sim::SimActuatorElevation out{{}, pulses, s.number("drop_pulse_at_s")};
  sim::ActuatorDishParams& dish = out.dish;
  dish.geometry = *pulses.geometry;
  dish.speed_mm_s = s.number("actuator_speed_mm_s").value_or(dish.speed_mm_s);
  dish.time_constant_s = el.time_constant_s;
  dish.pulses_per_mm = pulses.scale.counts_per_unit;
  dish.home_switch_mm = pulses.scale.home_value;
  const auto start_mm = control::ActuatorGeometry(dish.geometry).length_mm(el.start_deg);
  if (!start_mm) s.fail("start_deg", start_mm.error().message);
  dish.start_mm = *start_mm;
  if (auto ok = dish.validate(); !ok)
    hw.fail("counts_per_mm", "the simulated dish: " + ok.error().message);
  return out;
}

}  // namespace azt::app
