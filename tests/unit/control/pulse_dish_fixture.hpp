#pragma once
// The actuator dish of docs/hardware.md ("Linear actuators", 1 pulse per millimetre through the
// triangle) as a pulse-counted axis's plant, for DrivenAxis's and PortedStation's pulse tests:
// its parameters, the axis's pulse configuration, and its events through a ports::PulseInput.

#include <string>
#include <utility>
#include <vector>

#include "azt/control/pulse_axis.hpp"
#include "azt/ports/pulse_input.hpp"
#include "azt/sim/actuator_dish_plant.hpp"

namespace azt::control::pulse_dish {

inline constexpr double kTickS = 0.02;
inline constexpr double kHomeSwitchMm = 525.0;  // between the reed's pulses at 524.5 and 525.5 mm
inline constexpr double kStartDeg = 20.0;       // where the axis is believed to be before homing

inline sim::ActuatorDishParams dish() {
  sim::ActuatorDishParams p;
  p.geometry.pivot_to_fixed_mm = 650.0;
  p.geometry.pivot_to_moving_mm = 400.0;
  p.geometry.offset_deg = 48.0;
  p.geometry.retracted_mm = 520.0;
  p.geometry.extended_mm = 977.2;
  p.pulses_per_mm = 1.0;
  p.pulse_phase = 0.5;
  p.home_switch_mm = kHomeSwitchMm;
  p.start_mm = 700.0;
  return p;
}

inline PulseAxisConfig pulse_config() {
  PulseAxisConfig c;
  c.homing.seek_duty = -0.8;  // the switch is at the retracted (low) end
  c.homing.slow_duty = 0.3;
  c.homing.stop_s = 0.5;
  c.homing.max_travel_counts = 600;  // the whole stroke is 457 pulses
  c.homing.no_pulse_s = 2.0;
  c.homing.tolerance_counts = 0;  // the simulated switch makes at the same length every time
  c.scale = {PulseUnit::Millimetres, 1.0, kHomeSwitchMm};
  c.geometry = dish().geometry;
  return c;
}

/// The plant's events of its last step, as the Linux adapter would queue them.
class PlantPulses final : public ports::PulseInput {
 public:
  explicit PlantPulses(const sim::ActuatorDishPlant& plant) : plant_(plant) {}
  void queue(const std::vector<sim::ActuatorEvent>& events) {
    for (const auto& e : events) {
      switch (e.kind) {
        case sim::ActuatorEventKind::Pulse:
          edges_.push_back({ports::PulseLine::Pulse, true, e.at_s});
          break;
        case sim::ActuatorEventKind::HomeClosed:
          edges_.push_back({ports::PulseLine::Home, true, e.at_s});
          break;
        case sim::ActuatorEventKind::HomeOpened:
          edges_.push_back({ports::PulseLine::Home, false, e.at_s});
          break;
      }
    }
  }
  std::vector<ports::PulseEdge> take_edges() override { return std::exchange(edges_, {}); }
  [[nodiscard]] bool home_closed() const override { return plant_.home_closed(); }
  [[nodiscard]] std::string describe() const override { return "simulated reed"; }

 private:
  const sim::ActuatorDishPlant& plant_;
  std::vector<ports::PulseEdge> edges_;
};

}  // namespace azt::control::pulse_dish
