#pragma once

#include "azt/util/result.hpp"

namespace azt::sim {

/// A DC motor's winding temperature in virtual time: a single thermal mass heated by the
/// copper loss (∝ current², and the current ∝ duty for a motor held against its load) and cooled
/// towards the ambient air.
///
/// Model: the steady temperature at duty d is ambient + rise_at_full_duty·d², approached with
/// the time constant τ, discretised exactly: T ← T_ss + (T − T_ss)·e^(−dt/τ). Any dt is stable.
/// A first-order model: real windings have a fast and a slow constant (winding and frame); one
/// is enough to show a trip latching and clearing.
struct MotorThermalParams {
  double ambient_c = 20.0;
  double rise_at_full_duty_c = 80.0;  ///< steady rise above ambient at duty ±1
  double time_constant_s = 300.0;
  double start_c = 20.0;

  /// All finite; rise ≥ 0; τ > 0; errors name the field.
  [[nodiscard]] Result<MotorThermalParams> validate() const;
};

class MotorThermalPlant {
 public:
  /// Precondition: params.validate().ok().
  explicit MotorThermalPlant(const MotorThermalParams& params)
      : params_(params), temperature_c_(params.start_c) {}

  /// Advances by dt_s at `duty` (NaN counts as 0; clamped to ±1).
  void step(double duty, double dt_s);

  [[nodiscard]] double temperature_c() const { return temperature_c_; }
  /// The temperature the motor settles at if held at `duty`.
  [[nodiscard]] double steady_c(double duty) const;

 private:
  MotorThermalParams params_;
  double temperature_c_ = 20.0;
};

}  // namespace azt::sim
