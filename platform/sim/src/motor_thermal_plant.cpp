#include "azt/sim/motor_thermal_plant.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace azt::sim {

Result<MotorThermalParams> MotorThermalParams::validate() const {
  const auto finite = {ambient_c, rise_at_full_duty_c, time_constant_s, start_c};
  if (!std::all_of(finite.begin(), finite.end(), [](double v) { return std::isfinite(v); })) {
    return fail("motor thermal parameters must be finite");
  }
  if (rise_at_full_duty_c < 0.0) return fail("rise_at_full_duty_c must not be negative");
  if (time_constant_s <= 0.0) return fail("time_constant_s must be positive");
  return *this;
}

double MotorThermalPlant::steady_c(double duty) const {
  const double d = std::isfinite(duty) ? std::clamp(duty, -1.0, 1.0) : 0.0;
  return params_.ambient_c + params_.rise_at_full_duty_c * d * d;
}

void MotorThermalPlant::step(double duty, double dt_s) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) return;
  const double steady = steady_c(duty);
  temperature_c_ = steady + (temperature_c_ - steady) * std::exp(-dt_s / params_.time_constant_s);
}

}  // namespace azt::sim
