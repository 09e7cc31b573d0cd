#include "config/sim_actuator_config.hpp"

#include <algorithm>
#include <string>

#include "config/config_file.hpp"
#include "config/hardware_config.hpp"

namespace azt::app {
namespace {

/// The dish plant on the triangle `geometry`, started at [sim.el] start_deg (`el`), moving at
/// [sim.el] actuator_speed_mm_s; its reed and home switch are the caller's to set.
sim::ActuatorDishParams dish_on(const control::ActuatorGeometryConfig& geometry,
                                const ConfigSection& s, const sim::AxisParams& el) {
  sim::ActuatorDishParams dish;
  dish.geometry = geometry;
  dish.speed_mm_s = s.number("actuator_speed_mm_s").value_or(dish.speed_mm_s);
  dish.time_constant_s = el.time_constant_s;
  const control::ActuatorGeometry triangle(dish.geometry);
  // Unless given, the dish starts where its stroke allows (the plant's default of 0°, or the
  // travel's end, may be below the retracted end): a `hardware` file without [sim.el] loads.
  const double start_deg = s.has("start_deg") ? el.start_deg
                                              : std::clamp(el.start_deg, triangle.min_angle_deg(),
                                                           triangle.max_angle_deg());
  const auto start_mm = triangle.length_mm(start_deg);
  if (!start_mm) s.fail("start_deg", start_mm.error().message);
  dish.start_mm = *start_mm;
  return dish;
}

/// The reed counted from the home switch, or nullopt for a count the simulation does not fly.
std::optional<sim::SimActuatorElevation> reed_actuator(const HardwareAxisConfig& a,
                                                       const ConfigSection& s,
                                                       const sim::AxisParams& el) {
  const control::PulseAxisConfig& pulses = *a.pulses;
  // The simulated actuator has a reed: a count in degrees or a quadrature pair is not flown (the
  // elevation is then the plain plant, read through the hub, as for any other sensor).
  if (!pulses.geometry || a.pulse_lines.size() != 1) return std::nullopt;
  sim::ActuatorDishParams dish = dish_on(*pulses.geometry, s, el);
  dish.pulses_per_mm = pulses.scale.counts_per_unit;
  dish.home_switch_mm = pulses.scale.home_value;
  return sim::SimActuatorElevation{dish, sim::SimActuatorReed{pulses, s.number("drop_pulse_at_s")}};
}

/// The feedback pot on the ADC, or nullopt for a pot calibrated in degrees (the plain plant).
std::optional<sim::SimActuatorElevation> pot_actuator(const HardwareAxisConfig& a,
                                                      const ConfigSection& s,
                                                      const sim::AxisParams& el) {
  if (!a.pot.actuator) return std::nullopt;
  // A pot has no reed to lose a pulse of: the key would test nothing.
  if (s.has("drop_pulse_at_s")) {
    s.fail("drop_pulse_at_s",
           "loses a reed pulse, but [hardware.el] reads the actuator with a pot "
           "(pot_calibration_mm): remove it, or count pulses (sensor = \"pulses\")");
  }
  sim::ActuatorDishParams dish = dish_on(*a.pot.actuator, s, el);
  // No home switch on this actuator: the plant's (its edges unread) sits at the retracted end.
  dish.home_switch_mm = dish.geometry.retracted_mm;
  return sim::SimActuatorElevation{dish, a.pot};
}

}  // namespace

std::optional<sim::SimActuatorElevation> sim_actuator_from(const ConfigFile& file,
                                                           const sim::AxisParams& el) {
  const ConfigSection hw = file.section("hardware").child("el");
  const ConfigSection s = file.section("sim").child("el");
  // The hub's elevation is the plain plant's: its table is left to the daemon's reading.
  if (read_by_hub(hw.choice("sensor", kAxisSensorKinds, AxisSensorKind::Hub))) return std::nullopt;
  // The daemon's own reader (every key of the table checked as the daemon checks it); the lines
  // are not used, only their number.
  const HardwareAxisConfig a = read_hardware_axis(hw, "el", "gpiochip0");
  std::optional<sim::SimActuatorElevation> out;
  switch (a.sensor) {
    case AxisSensorKind::Hub:
      return std::nullopt;
    case AxisSensorKind::Pulses:
      out = reed_actuator(a, s, el);
      break;
    case AxisSensorKind::Mcp3008:
    case AxisSensorKind::Ads1115:
      out = pot_actuator(a, s, el);
      break;
  }
  if (!out) return std::nullopt;
  if (auto ok = out->dish.validate(); !ok) {
    hw.fail(out->pot() ? "pot_calibration_mm" : "counts_per_mm",
            "the simulated dish: " + ok.error().message);
  }
  return out;
}

}  // namespace azt::app
