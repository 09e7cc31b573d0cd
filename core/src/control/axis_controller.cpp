#include "azt/control/axis_controller.hpp"

#include <algorithm>
#include <cmath>

namespace azt::control {
namespace {

// Below this target rate the lead direction is meaningless (a target at its turning point).
constexpr double kMinLeadRateDegS = 1e-5;

double sign(double x) { return x < 0.0 ? -1.0 : 1.0; }

bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace

Result<AxisControlConfig> AxisControlConfig::make(const AxisControlConfig& c) {
  if (!std::isfinite(c.window_deg) || c.window_deg < 0.0 || c.window_deg > 2.0) {
    return fail("window_deg must be 0.0 to 2.0");
  }
  if (!finite_positive(c.lsb_deg) || c.lsb_deg > 1.0) return fail("lsb_deg must be in (0, 1]");
  if (!finite_positive(c.fast_zone_deg)) return fail("fast_zone_deg must be positive");
  if (!std::isfinite(c.tracking_speed) || c.tracking_speed <= 0.0 || c.tracking_speed > 1.0) {
    return fail("tracking_speed must be in (0, 1]");
  }
  if (!finite_positive(c.max_rate_deg_s)) return fail("max_rate_deg_s must be positive");
  if (!std::isfinite(c.ramp_s) || c.ramp_s < 0.0 || c.ramp_s > 30.0) {
    return fail("ramp_s must be 0 to 30 s");
  }
  if (!std::isfinite(c.min_duty) || c.min_duty < 0.0 || c.min_duty >= 0.9) {
    return fail("min_duty must be 0 to 0.9");
  }
  if (!finite_positive(c.time_constant_s) || c.time_constant_s > 10.0) {
    return fail("time_constant_s must be in (0, 10] s");
  }
  if (!std::isfinite(c.backlash_deg) || c.backlash_deg < 0.0 || c.backlash_deg > 5.0) {
    return fail("backlash_deg must be 0 to 5");
  }
  return c;
}

bool AxisController::is_leading(double target_rate_deg_s) const {
  return config_.lead && std::fabs(target_rate_deg_s) >= kMinLeadRateDegS;
}

double AxisController::goal_deg(double target_deg, double target_rate_deg_s) const {
  if (!is_leading(target_rate_deg_s)) return target_deg;
  return target_deg + sign(target_rate_deg_s) * config_.window_deg;
}

double AxisController::approach_speed_deg_s(double error_deg, double distance_deg) const {
  const double zone = std::fabs(error_deg) > config_.fast_zone_deg ? 1.0 : config_.tracking_speed;
  double speed = zone * config_.max_rate_deg_s;
  speed = std::min(speed, distance_deg / (4.0 * config_.time_constant_s));
  if (config_.ramp_s > 0.0) {
    const double accel_deg_s2 = config_.max_rate_deg_s / config_.ramp_s;
    speed = std::min(speed, std::sqrt(2.0 * accel_deg_s2 * distance_deg));
  }
  return speed;
}

double AxisController::slew_duty(double wanted, double dt_s) {
  if (config_.ramp_s <= 0.0) return duty_ = wanted;
  const double step = dt_s / config_.ramp_s;
  duty_ = std::clamp(wanted, duty_ - step, duty_ + step);
  return duty_;
}

double AxisController::update(double target_deg, double position_deg, double target_rate_deg_s,
                              double dt_s) {
  if (!std::isfinite(target_deg) || !std::isfinite(position_deg) || !(dt_s > 0.0)) {
    halt();
    return 0.0;
  }
  const double error_deg = target_deg - position_deg;
  const double to_goal_deg = goal_deg(target_deg, target_rate_deg_s) - position_deg;
  if (!moving_) {
    if (std::fabs(error_deg) <= config_.start_threshold_deg()) return slew_duty(0.0, dt_s);
    moving_ = true;
    move_direction_ = sign(to_goal_deg);
    ++starts_;
  }
  // A fixed goal is reached within 1 LSB: the approach speed is down to K·1 LSB there, so cutting
  // the duty coasts < 1 LSB. A led goal is reached when the reading gets to it or past it: the
  // target then has the whole window (plus up to a count of quantization) to cross, which is what
  // makes a coarse encoder's moves longer than one count.
  const bool leading = is_leading(target_rate_deg_s);
  const bool arrived =
      leading ? to_goal_deg * move_direction_ <= 0.0 : std::fabs(to_goal_deg) <= config_.lsb_deg;
  if (arrived) {
    moving_ = false;
    duty_ = 0.0;
    return duty_;
  }
  if (sign(to_goal_deg) != direction_) {
    takeup_left_deg_ = direction_ == 0.0 ? 0.0 : config_.backlash_deg;
    direction_ = sign(to_goal_deg);
  }
  // Feed-forward of the target's own rate: without it a proportional approach lags a moving goal
  // by rate/K (≈ 1 LSB of a 16-bit encoder at the Moon's 15°/h) and never quite arrives.
  const double planned_deg = std::fabs(to_goal_deg) + takeup_left_deg_;
  // Crossing a led goal must not take forever: keep at least K·½ LSB of approach speed (it coasts
  // an eighth of an LSB when cut).
  const double floor_deg_s = leading ? config_.lsb_deg / (8.0 * config_.time_constant_s) : 0.0;
  const double approach = std::max(approach_speed_deg_s(error_deg, planned_deg), floor_deg_s);
  const double velocity = std::clamp(direction_ * approach + target_rate_deg_s,
                                     -config_.max_rate_deg_s, config_.max_rate_deg_s);
  takeup_left_deg_ = std::max(0.0, takeup_left_deg_ - std::fabs(velocity) * dt_s);
  const double magnitude =
      config_.min_duty + (1.0 - config_.min_duty) * std::fabs(velocity) / config_.max_rate_deg_s;
  return slew_duty(sign(velocity) * magnitude, dt_s);
}

double AxisController::drive_open(double wanted, double dt_s) {
  if (!std::isfinite(wanted) || !(dt_s > 0.0)) {
    halt();
    return 0.0;
  }
  // Not a move towards a goal: when the test ends, the holding tick finds the axis at rest and
  // ramps the duty down (a soft stop) instead of cutting it as an arrived move would.
  moving_ = false;
  return slew_duty(std::clamp(wanted, -1.0, 1.0), dt_s);
}

void AxisController::halt() {
  duty_ = 0.0;
  moving_ = false;
}

}  // namespace azt::control
