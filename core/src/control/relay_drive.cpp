#include "azt/control/relay_drive.hpp"

#include <algorithm>
#include <cmath>

namespace azt::control {
namespace {

// Below this target rate the lead direction is meaningless (a target at its turning point); the
// same threshold as AxisController.
constexpr double kMinLeadRateDegS = 1e-5;

bool in_range(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

}  // namespace

std::string_view to_string(RelayCommand command) {
  switch (command) {
    case RelayCommand::Off:
      return "off";
    case RelayCommand::Forward:
      return "forward";
    case RelayCommand::Reverse:
      return "reverse";
  }
  return "unknown";
}

Result<RelayDriveConfig> RelayDriveConfig::make(const RelayDriveConfig& c) {
  if (!in_range(c.window_deg, 0.0, 10.0)) return fail("window_deg must be 0 to 10");
  if (!std::isfinite(c.lsb_deg) || c.lsb_deg <= 0.0 || c.lsb_deg > 1.0) {
    return fail("lsb_deg must be in (0, 1]");
  }
  if (!in_range(c.coast_deg, 0.0, 10.0)) return fail("coast_deg must be 0 to 10");
  if (!in_range(c.min_on_s, 0.0, 10.0)) return fail("min_on_s must be 0 to 10 s");
  if (!std::isfinite(c.reversal_dead_s) || c.reversal_dead_s <= 0.0 || c.reversal_dead_s > 60.0) {
    return fail("reversal_dead_s must be in (0, 60] s");
  }
  if (!in_range(c.min_off_s, 0.0, 600.0)) return fail("min_off_s must be 0 to 600 s");
  return c;
}

double RelayDrive::goal_deg(double target_deg, double target_rate_deg_s) const {
  if (!config_.lead || std::fabs(target_rate_deg_s) < kMinLeadRateDegS) return target_deg;
  return target_deg + (target_rate_deg_s < 0.0 ? -config_.window_deg : config_.window_deg);
}

bool RelayDrive::may_start(RelayCommand wanted, double now_s) const {
  if (!released_at_s_) return false;
  double wait_s = config_.min_off_s;
  // last_direction_ is Off before the first start: the direction the motor may still be turning
  // in is unknown, so either start counts as a reversal.
  if (wanted != last_direction_) wait_s = std::max(wait_s, config_.reversal_dead_s);
  return now_s - *released_at_s_ >= wait_s;
}

void RelayDrive::release(double now_s) {
  command_ = RelayCommand::Off;
  released_at_s_ = now_s;
}

RelayCommand RelayDrive::run(double target_deg, double position_deg, double now_s,
                             double rate_deg_s) {
  const double direction = command_ == RelayCommand::Forward ? 1.0 : -1.0;
  // Negative once the axis has passed the goal: the same test covers "within the band" and
  // "the error changed sign".
  const double remaining_deg = direction * (goal_deg(target_deg, rate_deg_s) - position_deg);
  const bool min_on_done = now_s - energised_at_s_ >= config_.min_on_s;
  if (min_on_done && remaining_deg <= config_.stop_distance_deg()) release(now_s);
  return command_;
}

RelayCommand RelayDrive::try_start(double target_deg, double position_deg, double now_s) {
  // The start test uses the target, not the led goal (as AxisController): an axis parked
  // window_deg ahead of a moving target waits for it to cross the whole window.
  const double error_deg = target_deg - position_deg;
  if (std::fabs(error_deg) <= config_.start_threshold_deg()) return RelayCommand::Off;
  const RelayCommand wanted = error_deg > 0.0 ? RelayCommand::Forward : RelayCommand::Reverse;
  if (!may_start(wanted, now_s)) return RelayCommand::Off;
  if (last_direction_ != RelayCommand::Off && wanted != last_direction_) ++reversals_;
  last_direction_ = wanted;
  command_ = wanted;
  energised_at_s_ = now_s;
  ++starts_;
  return command_;
}

RelayCommand RelayDrive::update(double target_deg, double position_deg, double now_s,
                                double target_rate_deg_s) {
  if (!std::isfinite(now_s)) {
    halt(now_s);
    return command_;
  }
  if (last_now_s_ && now_s < *last_now_s_) {
    // A monotonic clock never does this: trust nothing measured so far and restart every wait
    // in the new time base (waiting forever for the old base to come back is no option).
    release(now_s);
    last_now_s_ = now_s;
    return command_;
  }
  last_now_s_ = now_s;
  if (!released_at_s_) released_at_s_ = now_s;  // construction, or a halt without a valid time
  if (!std::isfinite(target_deg) || !std::isfinite(position_deg) ||
      !std::isfinite(target_rate_deg_s)) {
    halt(now_s);
    return command_;
  }
  if (command_ == RelayCommand::Off) return try_start(target_deg, position_deg, now_s);
  return run(target_deg, position_deg, now_s, target_rate_deg_s);
}

void RelayDrive::halt(double now_s) {
  if (command_ == RelayCommand::Off) return;
  command_ = RelayCommand::Off;
  if (std::isfinite(now_s)) {
    released_at_s_ = now_s;
  } else {
    released_at_s_.reset();
  }
}

Result<PowerPolarityConfig> PowerPolarityConfig::make(const PowerPolarityConfig& c) {
  if (!std::isfinite(c.dead_s) || c.dead_s <= 0.0 || c.dead_s > 60.0) {
    return fail("dead_s must be in (0, 60] s");
  }
  if (!in_range(c.settle_s, 0.0, 1.0)) return fail("settle_s must be 0 to 1 s");
  return c;
}

void PowerPolarityRelays::power_off(double now_s) {
  if (!output_.power) return;
  output_.power = false;
  off_since_s_ = now_s;
}

void PowerPolarityRelays::halt(double now_s) {
  if (!output_.power) return;
  output_.power = false;
  if (std::isfinite(now_s)) {
    off_since_s_ = now_s;
  } else {
    off_since_s_.reset();
  }
}

PowerPolarity PowerPolarityRelays::update(RelayCommand command, double now_s) {
  if (!std::isfinite(now_s)) {
    halt(now_s);
    return output_;
  }
  if (last_now_s_ && now_s < *last_now_s_) {
    // As in RelayDrive: restart every wait in the new time base.
    output_.power = false;
    off_since_s_ = now_s;
    polarity_since_s_ = now_s;
    last_now_s_ = now_s;
    return output_;
  }
  last_now_s_ = now_s;
  if (!off_since_s_) off_since_s_ = now_s;
  if (!polarity_since_s_) polarity_since_s_ = now_s;
  if (command == RelayCommand::Off) {
    power_off(now_s);
    return output_;
  }
  const bool want_reverse = command == RelayCommand::Reverse;
  if (want_reverse != output_.reverse) {
    power_off(now_s);
    if (now_s - *off_since_s_ >= config_.dead_s) {
      output_.reverse = want_reverse;
      polarity_since_s_ = now_s;
    }
    return output_;  // power never closes on the tick the polarity moved
  }
  if (!output_.power && now_s - *polarity_since_s_ >= config_.settle_s) output_.power = true;
  return output_;
}

}  // namespace azt::control
