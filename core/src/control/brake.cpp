#include "azt/control/brake.hpp"

#include <algorithm>
#include <cmath>

namespace azt::control {
namespace {

bool in_range(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

}  // namespace

std::string_view to_string(BrakeState state) {
  switch (state) {
    case BrakeState::Engaged:
      return "engaged";
    case BrakeState::Releasing:
      return "releasing";
    case BrakeState::Released:
      return "released";
    case BrakeState::Idle:
      return "released, idle";
    case BrakeState::Engaging:
      return "engaging";
  }
  return "unknown";
}

Result<BrakeConfig> BrakeConfig::make(const BrakeConfig& c) {
  // A brake that releases in no time is a configuration without a brake: say so with 0 < x.
  if (!in_range(c.release_s, 0.0, 10.0) || c.release_s == 0.0) {
    return fail("release_s must be above 0 and at most 10 s");
  }
  if (!in_range(c.engage_s, 0.0, 10.0)) return fail("engage_s must be 0 to 10 s");
  if (!in_range(c.idle_s, 0.0, 600.0)) return fail("idle_s must be 0 to 600 s");
  return c;
}

bool Brake::release_output() const {
  switch (state_) {
    case BrakeState::Releasing:
    case BrakeState::Released:
    case BrakeState::Idle:
      return true;
    case BrakeState::Engaged:
    case BrakeState::Engaging:
      return false;
  }
  return false;
}

void Brake::enter(BrakeState state, double now_s) {
  state_ = state;
  since_s_ = now_s;
}

void Brake::engage(double now_s) {
  ++engagements_;
  enter(BrakeState::Engaging, now_s);
}

void Brake::advance(bool wants_motion, double now_s) {
  const double in_state_s = now_s - since_s_;
  switch (state_) {
    case BrakeState::Engaged:
      if (wants_motion) enter(BrakeState::Releasing, now_s);
      return;
    case BrakeState::Releasing:
      // Finishes even if the wish went away meanwhile: Idle then applies it after idle_s.
      if (in_state_s >= config_.release_s) {
        enter(wants_motion ? BrakeState::Released : BrakeState::Idle, now_s);
      }
      return;
    case BrakeState::Released:
      if (!wants_motion) enter(BrakeState::Idle, now_s);
      return;
    case BrakeState::Idle:
      if (wants_motion) {
        enter(BrakeState::Released, now_s);
      } else if (in_state_s >= config_.idle_s) {
        engage(now_s);
      }
      return;
    case BrakeState::Engaging:
      // A new move waits for the brake to hold, then releases it fully.
      if (in_state_s >= config_.engage_s) {
        enter(wants_motion ? BrakeState::Releasing : BrakeState::Engaged, now_s);
      }
      return;
  }
}

double Brake::update(double wanted_duty, double now_s) {
  if (!std::isfinite(wanted_duty) || !std::isfinite(now_s) ||
      (last_now_s_ && now_s < *last_now_s_)) {
    halt(now_s);
    return 0.0;
  }
  last_now_s_ = now_s;
  advance(wanted_duty != 0.0, now_s);
  return state_ == BrakeState::Released ? wanted_duty : 0.0;
}

void Brake::halt(double now_s) {
  if (!release_output()) return;
  // The engage time runs from the latest time seen: a time that is not a number or jumps back
  // cannot shorten it.
  double from_s = last_now_s_.value_or(std::isfinite(now_s) ? now_s : 0.0);
  if (std::isfinite(now_s)) from_s = std::max(from_s, now_s);
  engage(from_s);
}

}  // namespace azt::control
