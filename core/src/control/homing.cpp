#include "azt/control/homing.hpp"

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>

#include "azt/util/format_number.hpp"

namespace azt::control {
namespace {

// Counts the wrong way (away from the switch while seeking it) before homing gives up: more
// than a quadrature sensor's jitter at rest (±1), and a motor or sensor wired the wrong way
// round gets there within a second. A single channel counts the drive's way and never does.
constexpr std::int64_t kWrongWayCounts = 8;

bool in_range(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

bool duty_ok(double duty) { return std::isfinite(duty) && duty != 0.0 && std::fabs(duty) <= 1.0; }

}  // namespace

std::string_view to_string(HomingState state) {
  switch (state) {
    case HomingState::NotHomed:
      return "not homed";
    case HomingState::Seeking:
      return "seeking";
    case HomingState::Stopping:
      return "stopping";
    case HomingState::BackingOff:
      return "backing off";
    case HomingState::Reapproaching:
      return "re-approaching";
    case HomingState::Homed:
      return "homed";
    case HomingState::Failed:
      return "homing failed";
    case HomingState::PositionLost:
      return "position lost";
  }
  return "unknown";
}

Result<HomingConfig> HomingConfig::make(const HomingConfig& c) {
  if (!duty_ok(c.seek_duty)) return fail("seek_duty must be non-zero, -1 to 1");
  if (!duty_ok(c.slow_duty) || c.slow_duty < 0.0) return fail("slow_duty must be in (0, 1]");
  if (!in_range(c.stop_s, 0.0, 60.0)) return fail("stop_s must be 0 to 60 s");
  if (!in_range(c.backoff_s, 0.0, 60.0)) return fail("backoff_s must be 0 to 60 s");
  if (!in_range(c.phase_timeout_s, 1.0, 3600.0)) return fail("phase_timeout_s must be 1 to 3600 s");
  if (c.max_travel_counts <= 0) return fail("max_travel_counts must be positive");
  if (!in_range(c.no_pulse_s, 0.1, 600.0)) return fail("no_pulse_s must be 0.1 to 600 s");
  if (c.tolerance_counts < 0) return fail("tolerance_counts must not be negative");
  return c;
}

bool Homing::active() const {
  switch (state_) {
    case HomingState::Seeking:
    case HomingState::Stopping:
    case HomingState::BackingOff:
    case HomingState::Reapproaching:
      return true;
    case HomingState::NotHomed:
    case HomingState::Homed:
    case HomingState::Failed:
    case HomingState::PositionLost:
      return false;
  }
  return false;
}

void Homing::enter(HomingState state, double now_s, std::int64_t count) {
  state_ = state;
  phase_start_s_ = now_s;
  phase_start_count_ = count;
  last_pulse_s_ = now_s;
  last_count_ = count;
  switch_open_since_s_.reset();
  if (state == HomingState::BackingOff && !switch_closed_) switch_open_since_s_ = now_s;
}

void Homing::fail_with(std::string reason) {
  state_ = HomingState::Failed;
  reason_ = std::move(reason);
}

void Homing::start(double now_s, std::int64_t count, bool switch_closed) {
  reason_.clear();
  last_pass_.reset();
  seek_edge_count_.reset();
  switch_closed_ = switch_closed;
  if (!std::isfinite(now_s)) {
    fail_with("homing could not start: the time is not a number");
    return;
  }
  last_now_s_ = now_s;
  // Already on the switch: its make point is behind us; back off and come back to it.
  after_stop_ = HomingState::BackingOff;
  enter(switch_closed ? HomingState::Stopping : HomingState::Seeking, now_s, count);
}

void Homing::on_switch(bool closed, double at_s, std::int64_t count) {
  switch_closed_ = closed;
  if (closed) {
    on_switch_closed(at_s, count);
  } else if (state_ == HomingState::BackingOff && !switch_open_since_s_) {
    switch_open_since_s_ = at_s;
  }
}

void Homing::on_switch_closed(double at_s, std::int64_t count) {
  switch (state_) {
    case HomingState::Seeking:
      seek_edge_count_ = count;
      after_stop_ = HomingState::BackingOff;
      enter(HomingState::Stopping, at_s, count);
      return;
    case HomingState::Reapproaching:
      home_count_ = count;
      last_pass_ = 0;
      state_ = HomingState::Homed;
      return;
    case HomingState::BackingOff:
      switch_open_since_s_.reset();  // bounce, or not yet clear of it: the wait starts again
      return;
    case HomingState::Homed:
      check_pass(count);
      return;
    case HomingState::NotHomed:
    case HomingState::Stopping:
    case HomingState::Failed:
    case HomingState::PositionLost:
      return;
  }
}

void Homing::check_pass(std::int64_t count) {
  const std::int64_t difference = count - home_count_;
  last_pass_ = difference;
  const std::int64_t lost = std::llabs(difference);
  if (lost <= config_.tolerance_counts) return;
  state_ = HomingState::PositionLost;
  reason_ = "position lost: " + std::to_string(lost) + (lost == 1 ? " count" : " counts") +
            " lost (the home switch closed at count " + std::to_string(count) +
            ", homing found it at " + std::to_string(home_count_) + "; tolerance " +
            std::to_string(config_.tolerance_counts) + ")";
}

double Homing::update(double now_s, std::int64_t count) {
  if (!std::isfinite(now_s) || (last_now_s_ && now_s < *last_now_s_)) {
    if (active()) fail_with("homing stopped: the time went backwards or is not a number");
    return 0.0;
  }
  last_now_s_ = now_s;
  if (!active()) return 0.0;
  if (count != last_count_) {
    last_count_ = count;
    last_pulse_s_ = now_s;
  }
  if (state_ == HomingState::Stopping) {
    if (now_s - phase_start_s_ >= config_.stop_s) finish_stop(now_s, count);
  } else {
    check_phase(now_s, count);
  }
  return phase_duty();
}

void Homing::finish_stop(double now_s, std::int64_t count) {
  if (after_stop_ != HomingState::Homed) {
    enter(after_stop_, now_s, count);
    return;
  }
  // Without the re-approach the home count is the seek's, taken at its (faster) edge.
  home_count_ = seek_edge_count_.value_or(count);
  last_pass_ = 0;
  state_ = HomingState::Homed;
}

std::int64_t Homing::progress_counts(std::int64_t count) const {
  const std::int64_t towards = config_.seek_duty > 0.0 ? 1 : -1;
  const std::int64_t way = state_ == HomingState::BackingOff ? -towards : towards;
  return way * (count - phase_start_count_);
}

std::optional<std::string> Homing::phase_failure(double now_s, std::int64_t count) const {
  const std::string phase{phase_name()};
  const std::int64_t progress = progress_counts(count);
  if (now_s - phase_start_s_ > config_.phase_timeout_s) {
    return phase + ": gave up after " + format_number(config_.phase_timeout_s) + " s" +
           (state_ == HomingState::BackingOff
                ? " with the home switch still closed (a stuck switch or its wiring)"
                : " without the home switch");
  }
  if (std::llabs(progress) > config_.max_travel_counts) {
    return phase + ": travelled " + std::to_string(std::llabs(progress)) +
           " counts without the home switch (max_travel_counts " +
           std::to_string(config_.max_travel_counts) + ")";
  }
  if (progress <= -kWrongWayCounts) {
    return phase + ": counted " + std::to_string(-progress) +
           " counts the wrong way (a motor or a sensor wired the other way round)";
  }
  if (now_s - last_pulse_s_ > config_.no_pulse_s) {
    return phase + ": no pulses for " + format_fixed(now_s - last_pulse_s_, 1) +
           " s while driven (the motor, the pulse sensor or its wiring)";
  }
  return std::nullopt;
}

void Homing::check_phase(double now_s, std::int64_t count) {
  if (auto failure = phase_failure(now_s, count)) {
    fail_with(std::move(*failure));
    return;
  }
  const bool backed_off = state_ == HomingState::BackingOff && switch_open_since_s_ &&
                          now_s - *switch_open_since_s_ >= config_.backoff_s;
  if (!backed_off) return;
  // Without the re-approach, the seek's edge is the home count; starting on the switch there was
  // no seek edge, so seek now.
  after_stop_ = config_.reapproach ? HomingState::Reapproaching
                : seek_edge_count_ ? HomingState::Homed
                                   : HomingState::Seeking;
  enter(HomingState::Stopping, now_s, count);
}

double Homing::phase_duty() const {
  const double towards = config_.seek_duty > 0.0 ? 1.0 : -1.0;
  switch (state_) {
    case HomingState::Seeking:
      return config_.seek_duty;
    case HomingState::BackingOff:
      return -towards * config_.slow_duty;
    case HomingState::Reapproaching:
      return towards * config_.slow_duty;
    case HomingState::NotHomed:
    case HomingState::Stopping:
    case HomingState::Homed:
    case HomingState::Failed:
    case HomingState::PositionLost:
      return 0.0;
  }
  return 0.0;
}

std::string_view Homing::phase_name() const {
  switch (state_) {
    case HomingState::Seeking:
      return "seeking the home switch";
    case HomingState::Stopping:
      return "stopping";
    case HomingState::BackingOff:
      return "backing off the home switch";
    case HomingState::Reapproaching:
      return "re-approaching the home switch slowly";
    case HomingState::NotHomed:
    case HomingState::Homed:
    case HomingState::Failed:
    case HomingState::PositionLost:
      return "homing";
  }
  return "homing";
}

void Homing::abort(std::string_view reason) {
  if (!active()) return;
  state_ = HomingState::NotHomed;
  reason_ = "homing stopped: " + std::string{reason};
}

void Homing::reset() {
  state_ = HomingState::NotHomed;
  reason_.clear();
  last_pass_.reset();
}

std::optional<std::string> Homing::why_not_homed() const {
  switch (state_) {
    case HomingState::Homed:
      return std::nullopt;
    case HomingState::NotHomed:
      return "not homed: " + (reason_.empty() ? std::string{"homing has not run"} : reason_);
    case HomingState::Seeking:
    case HomingState::Stopping:
    case HomingState::BackingOff:
    case HomingState::Reapproaching:
      return "not homed: homing in progress (" + std::string{phase_name()} + ")";
    case HomingState::Failed:
      return "not homed: homing failed: " + reason_;
    case HomingState::PositionLost:
      return "not homed: " + reason_ + "; home again";
  }
  return "not homed";
}

std::optional<std::int64_t> Homing::counts_from_home(std::int64_t count) const {
  if (state_ != HomingState::Homed) return std::nullopt;
  return count - home_count_;
}

}  // namespace azt::control
