#include "azt/control/supervisor.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "azt/util/format_number.hpp"

namespace azt::control {
namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace

std::string_view to_string(FaultKind kind) {
  switch (kind) {
    case FaultKind::None:
      return "none";
    case FaultKind::StalePosition:
      return "stale_position";
    case FaultKind::Stall:
      return "stall";
    case FaultKind::Runaway:
      return "runaway";
    case FaultKind::EncoderJump:
      return "encoder_jump";
    case FaultKind::EStop:
      return "estop";
    case FaultKind::MotorTrip:
      return "motor_trip";
    case FaultKind::PositionLost:
      return "position_lost";
  }
  return "none";
}

Result<SupervisorConfig> SupervisorConfig::make(const SupervisorConfig& c) {
  if (!positive(c.stale_s) || !positive(c.stall_window_s) || !positive(c.stall_min_move_deg) ||
      !positive(c.driven_duty) || c.driven_duty > 1.0 || !positive(c.runaway_deg) ||
      !positive(c.max_rate_deg_s) || !std::isfinite(c.jump_margin_deg) || c.jump_margin_deg < 0.0 ||
      !positive(c.jump_persist_s) || !std::isfinite(c.lsb_deg) || c.lsb_deg < 0.0) {
    return fail("supervisor limits must be positive and finite (driven_duty at most 1)");
  }
  return c;
}

bool AxisSupervisor::on_reading(double now_s, double position_deg) {
  if (!std::isfinite(position_deg)) return false;
  if (last_good_deg_) {
    const double dt_s = std::max(now_s - last_good_s_, 0.0);
    const double margin_deg = std::max(config_.jump_margin_deg, 2.0 * config_.lsb_deg);
    const double plausible = config_.max_rate_deg_s * dt_s + margin_deg;
    if (std::fabs(position_deg - *last_good_deg_) > plausible) {
      if (!first_rejected_s_) first_rejected_s_ = now_s;
      if (now_s - *first_rejected_s_ >= config_.jump_persist_s && fault_ == FaultKind::None) {
        latch(FaultKind::EncoderJump, "position jumped from " + format_number(*last_good_deg_) +
                                          " to " + format_number(position_deg) + " deg and stayed");
      }
      return false;
    }
  }
  first_rejected_s_.reset();
  last_good_deg_ = position_deg;
  last_good_s_ = now_s;
  return true;
}

bool AxisSupervisor::stale(double now_s) const {
  return !last_good_deg_ || now_s - last_good_s_ > config_.stale_s;
}

void AxisSupervisor::latch(FaultKind kind, std::string reason) {
  fault_ = kind;
  reason_ = std::move(reason);
  driven_since_s_.reset();
}

void AxisSupervisor::watch_motion(double now_s, double duty) {
  const double direction = duty > 0.0 ? 1.0 : -1.0;
  if (std::fabs(duty) < config_.driven_duty ||
      (driven_since_s_ && direction != driven_direction_)) {
    driven_since_s_.reset();
    if (std::fabs(duty) < config_.driven_duty) return;
  }
  if (!driven_since_s_) {
    driven_since_s_ = now_s;
    driven_start_deg_ = *last_good_deg_;
    driven_best_progress_deg_ = 0.0;
    driven_direction_ = direction;
    return;
  }
  const double elapsed_s = now_s - *driven_since_s_;
  // Against the best progress so far: a motor that reverses mid-move is caught as soon as it has
  // gone back by runaway_deg, not only once it is behind where the stretch started.
  const double progress_deg = driven_direction_ * (*last_good_deg_ - driven_start_deg_);
  driven_best_progress_deg_ = std::max(driven_best_progress_deg_, progress_deg);
  if (driven_best_progress_deg_ - progress_deg > config_.runaway_deg) {
    latch(FaultKind::Runaway, "driven one way for " + format_number(elapsed_s) +
                                  " s but moved more than " + format_number(config_.runaway_deg) +
                                  " deg the other way (motor reversed?)");
    return;
  }
  if (elapsed_s < config_.stall_window_s) return;
  if (std::fabs(*last_good_deg_ - driven_start_deg_) < config_.stall_min_move_deg) {
    latch(FaultKind::Stall, "driven for " + format_number(config_.stall_window_s) +
                                " s but moved less than " +
                                format_number(config_.stall_min_move_deg) + " deg");
    return;
  }
  // Healthy: start a new observation window from here.
  driven_since_s_ = now_s;
  driven_start_deg_ = *last_good_deg_;
  driven_best_progress_deg_ = 0.0;
}

SupervisorVerdict AxisSupervisor::check(double now_s, double duty) {
  SupervisorVerdict verdict;
  if (fault_ != FaultKind::None) return verdict;
  if (stale(now_s)) {
    driven_since_s_.reset();
    return verdict;
  }
  verdict.position_deg = last_good_deg_;
  watch_motion(now_s, duty);
  verdict.allow_motion = fault_ == FaultKind::None;
  return verdict;
}

void AxisSupervisor::rebase(double delta_deg) {
  if (last_good_deg_) *last_good_deg_ += delta_deg;
  driven_start_deg_ += delta_deg;
}

void AxisSupervisor::emergency_stop(double /*now_s*/, std::string_view reason) {
  latch(FaultKind::EStop, std::string(reason));
}

void AxisSupervisor::clear() {
  fault_ = FaultKind::None;
  reason_.clear();
  first_rejected_s_.reset();
  driven_since_s_.reset();
}

}  // namespace azt::control
