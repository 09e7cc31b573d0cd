#include "azt/control/step_dir.hpp"

#include <algorithm>
#include <cmath>

namespace azt::control {

Result<StepDirConfig> StepDirConfig::make(double max_step_hz, double start_hz, double accel_hz_s) {
  if (!std::isfinite(max_step_hz) || max_step_hz <= 0.0) {
    return fail("the full step rate must be a positive number");
  }
  if (!std::isfinite(start_hz) || start_hz < 0.0 || start_hz > max_step_hz) {
    return fail("the start rate must be between 0 and the full step rate");
  }
  if (!std::isfinite(accel_hz_s) || accel_hz_s <= 0.0) {
    return fail("the acceleration must be a positive number");
  }
  return StepDirConfig{max_step_hz, start_hz, accel_hz_s};
}

double StepDir::next_rate(double wanted_hz, double dt_s) const {
  // A millionth of a hertz is no rate: the sums of a ramp land on the band's edge, not beside it.
  constexpr double kSlackHz = 1e-6;
  const double band = config_.start_hz;
  // Inside the pull-in band the rotor follows a new rate at once, from a standstill too.
  if (rate_hz_ <= band + kSlackHz && wanted_hz <= band) return wanted_hz;
  // From below the band: to its edge first, where the ramp starts.
  if (rate_hz_ < band - kSlackHz) return std::min(wanted_hz, band);
  const double step = config_.accel_hz_s * dt_s;
  if (wanted_hz > rate_hz_) return std::min(wanted_hz, rate_hz_ + step);
  // Slowing down (from above the band): to its edge at most, from where the next tick stops.
  const double slower = std::max(wanted_hz, rate_hz_ - step);
  return slower < band + kSlackHz ? std::max(wanted_hz, band) : slower;
}

StepDirOutputs StepDir::drive(double now_s, double duty) {
  if (!std::isfinite(duty)) return disable(now_s);  // a bad number stops, never steps
  const double dt_s = last_s_ ? std::clamp(now_s - *last_s_, 0.0, 1.0) : 0.0;
  last_s_ = now_s;
  duty = std::clamp(duty, -1.0, 1.0);
  const int wanted_direction = duty > 0.0 ? 1 : (duty < 0.0 ? -1 : 0);
  // The other way: slow to a standstill first (the rate wanted this way is none).
  const bool reversing = wanted_direction != 0 && wanted_direction != direction_;
  double wanted_hz = reversing ? 0.0 : std::fabs(duty) * config_.max_step_hz;
  if (wanted_hz < StepDirConfig::kMinStepHz) wanted_hz = 0.0;
  if (reversing && rate_hz_ == 0.0) {
    direction_ = wanted_direction;  // DIR set now; the first step comes next tick
    return StepDirOutputs{0.0, direction_, true};
  }
  rate_hz_ = next_rate(wanted_hz, dt_s);
  return StepDirOutputs{rate_hz_, direction_, true};
}

StepDirOutputs StepDir::disable(double now_s) {
  last_s_ = now_s;
  rate_hz_ = 0.0;
  return StepDirOutputs{0.0, direction_, false};
}

}  // namespace azt::control
