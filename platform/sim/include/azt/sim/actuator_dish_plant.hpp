#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "azt/control/actuator_geometry.hpp"
#include "azt/util/result.hpp"

namespace azt::sim {

/// A dish axis on a linear actuator, with a reed sensor and a home switch, in virtual time.
///
/// Model, per step(duty, dt_s) with the duty held for dt_s:
///  1. The motor's rate (mm/s of actuator length) follows duty through a dead zone and a first
///     order lag, exactly as AxisPlant's (axis_plant.hpp): commanded rate
///     speed·(|d| − s)/(1 − s), signed, and ω ← ω_c + (ω − ω_c)·e^(−dt/τ), the length by the
///     exact integral. So the actuator coasts after the duty drops, and the reed counts the coast.
///     Positive duty extends the actuator.
///  2. The actuator's own end switches stop it at its retracted and extended lengths (the rate
///     towards the end is zeroed).
///  3. The axis angle is the geometry's angle of the length (control::ActuatorGeometry).
///  4. The reed closes once per 1/pulses_per_mm of length, at retracted + (k + phase)/ppm, in
///     either direction of travel; each crossing is a pulse event stamped at the time the length
///     passed it (interpolated linearly within the step: keep dt small against the pulse period).
///  5. The home switch is closed at lengths ≤ home_switch_mm; its edges are events too.
///  6. drop_pulse_after(t): the first pulse at or after t is not emitted (a pulse lost to motor
///     noise, a slipped magnet): the counter is then one count off, which only the home switch
///     can reveal.
struct ActuatorDishParams {
  control::ActuatorGeometryConfig geometry;
  double speed_mm_s = 8.0;        ///< actuator speed at full duty
  double time_constant_s = 0.15;  ///< motor speed response (sets the coast after a stop)
  double stiction_duty = 0.1;     ///< |duty| at or below this does not turn the motor
  double pulses_per_mm = 1.0;     ///< reed pulses per millimetre of length
  double pulse_phase = 0.5;       ///< where within a pitch the reed closes, [0, 1)
  double home_switch_mm = 0.0;    ///< the home switch is closed at and below this length
  double start_mm = 0.0;          ///< the length at construction

  /// Checks every field (the geometry through ActuatorGeometryConfig::make, the switch and the
  /// start within the stroke, positive speed and τ, 0 ≤ stiction < 1, 0 < ppm ≤ 100,
  /// 0 ≤ phase < 1); errors name the field.
  [[nodiscard]] Result<ActuatorDishParams> validate() const;
};

enum class ActuatorEventKind : std::uint8_t { Pulse, HomeClosed, HomeOpened };

std::string_view to_string(ActuatorEventKind kind);

struct ActuatorEvent {
  ActuatorEventKind kind = ActuatorEventKind::Pulse;
  double at_s = 0.0;
};

class ActuatorDishPlant {
 public:
  /// Precondition: params.validate().ok() (use make() when unsure).
  explicit ActuatorDishPlant(const ActuatorDishParams& params);
  static Result<ActuatorDishPlant> make(const ActuatorDishParams& params);

  /// Advances by dt_s with `duty` held (clamped to ±1; NaN counts as 0). Returns the pulse and
  /// switch events of the step in time order. dt_s ≤ 0 or non-finite does nothing.
  std::vector<ActuatorEvent> step(double duty, double dt_s);

  [[nodiscard]] double now_s() const { return now_s_; }
  [[nodiscard]] double length_mm() const { return length_mm_; }
  [[nodiscard]] double rate_mm_s() const { return rate_mm_s_; }
  /// The axis angle the geometry gives for the length (the truth a test compares with).
  [[nodiscard]] double angle_deg() const;
  [[nodiscard]] bool home_closed() const { return length_mm_ <= params_.home_switch_mm; }
  [[nodiscard]] const control::ActuatorGeometry& geometry() const { return geometry_; }
  [[nodiscard]] const ActuatorDishParams& params() const { return params_; }

  void drop_pulse_after(double at_s) { drop_after_s_ = at_s; }
  [[nodiscard]] std::uint64_t pulses_emitted() const { return emitted_; }
  [[nodiscard]] std::uint64_t pulses_dropped() const { return dropped_; }

 private:
  [[nodiscard]] double commanded_rate_mm_s(double duty) const;
  void move(double duty, double dt_s);
  void add_pulses(double from_mm, double to_mm, double dt_s, std::vector<ActuatorEvent>& events);
  void add_switch_edge(double from_mm, double to_mm, double dt_s,
                       std::vector<ActuatorEvent>& events) const;
  [[nodiscard]] double crossing_s(double from_mm, double to_mm, double at_mm, double dt_s) const;

  ActuatorDishParams params_;
  control::ActuatorGeometry geometry_;
  double now_s_ = 0.0;
  double length_mm_ = 0.0;
  double rate_mm_s_ = 0.0;
  std::optional<double> drop_after_s_;
  std::uint64_t emitted_ = 0;
  std::uint64_t dropped_ = 0;
};

}  // namespace azt::sim
