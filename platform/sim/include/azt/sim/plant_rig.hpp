#pragma once
// What a simulated station's ports share: the plants (and the polarisation plant, if any), the
// faults due to them, the hub reading their encoders, and the duties the drives last set. The first
// sensor read at a new time runs the plants and the hub for the time since the last one (capped at
// 1 s, after a suspend), in the hub's steps, with the duties then applied (a late tick is simulated
// exactly as long as it was late); then both axes report the hub's newest frame, each once.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "azt/ports/pulse_input.hpp"

#include "azt/sim/fault_schedule.hpp"
#include "azt/sim/plant_setup.hpp"
#include "azt/sim/sim_antenna.hpp"
#include "azt/sim/simulated_hub.hpp"

namespace azt::sim {

class PlantRig {
 public:
  PlantRig(const PlantSetup& plant, std::unique_ptr<SimulatedHub> hub);

  void set_duty(std::size_t axis, double duty) { duty_.at(axis) = duty; }
  /// The brake line of `axis` (no brake plant: ignored).
  void set_brake(std::size_t axis, bool release) { brake_on_.at(axis) = release; }
  /// The motor temperature of `axis` at `now_s`, once the plants have run up to it; nullopt
  /// without a thermal plant.
  std::optional<double> motor_temperature_c(std::size_t axis, double now_s);
  /// The polarisation plant's duty (no pol plant: ignored).
  void set_pol_duty(double duty) { pol_duty_ = duty; }
  /// The duty the drive last set on `axis`.
  [[nodiscard]] double duty(std::size_t axis) const { return duty_.at(axis); }
  /// The frame that is new to `axis` at `now_s`, if any.
  std::optional<HubArrival> frame_for(std::size_t axis, double now_s);
  /// The polarisation encoder's count at `now_s`, once the plants have run up to it; nullopt
  /// without a pol plant.
  std::optional<std::uint16_t> pol_raw(double now_s);

  /// The plants' truth (shaft angles, motor rates): what a simulation measures the station by.
  [[nodiscard]] const SimAntenna& plants() const { return plants_; }
  [[nodiscard]] const SimulatedHub& hub() const { return *hub_; }
  /// The polarisation plant's truth; nullptr without one.
  [[nodiscard]] const AxisPlant* pol_plant() const { return pol_ ? &*pol_ : nullptr; }
  /// The elevation actuator's length at `now_s`, once the plants have run up to it (what its
  /// feedback pot reads); nullopt without an actuator.
  std::optional<double> el_length_mm(double now_s);
  /// The elevation actuator's reed and home switch edges since the last call (the plants run up
  /// to the last read), on the loop's clock; none without an actuator or with a pot on it.
  std::vector<ports::PulseEdge> take_el_edges() { return std::exchange(el_edges_, {}); }
  /// The elevation actuator's home switch now (false without one).
  [[nodiscard]] bool el_home_closed() const { return el_dish_ && el_dish_->home_closed(); }
  /// The elevation actuator; nullptr without one.
  [[nodiscard]] const ActuatorDishPlant* el_dish() const { return el_dish_ ? &*el_dish_ : nullptr; }
  /// The brake of `axis`; nullptr without one.
  [[nodiscard]] const BrakePlant* brake(std::size_t axis) const {
    return brakes_.at(axis) ? &*brakes_.at(axis) : nullptr;
  }

 private:
  void advance(double now_s);
  /// The elevation actuator for one step of the hub ending at `end_s` on the loop's clock: its
  /// edges queued, the el plant following it.
  void step_el_dish(double duty, double step_s, double end_s);

  FaultSchedule faults_;
  SimAntenna plants_;
  std::unique_ptr<SimulatedHub> hub_;
  std::array<double, 2> duty_{};
  std::optional<AxisPlant> pol_;
  std::array<std::optional<BrakePlant>, 2> brakes_;
  std::array<bool, 2> brake_on_{};
  std::array<std::optional<MotorThermalPlant>, 2> thermal_;
  double pol_duty_ = 0.0;
  std::optional<ActuatorDishPlant> el_dish_;
  std::vector<ports::PulseEdge> el_edges_;
  bool el_counted_ = false;  ///< the actuator's reed is read (not a pot): its edges are queued
  std::optional<double> first_s_;  ///< the configured faults are timed from the first read
  std::optional<double> last_s_;
  std::optional<HubArrival> frame_;
  std::array<bool, 2> fresh_{};
};

}  // namespace azt::sim
