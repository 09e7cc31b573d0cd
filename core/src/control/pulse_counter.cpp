#include "azt/control/pulse_counter.hpp"

#include <cmath>

namespace azt::control {
namespace {

// Which calls an input kind takes: a switch, so a new kind must say.
bool takes_pulses(PulseInputKind kind) {
  switch (kind) {
    case PulseInputKind::SingleChannel:
      return true;
    case PulseInputKind::Quadrature:
      return false;
  }
  return false;
}

}  // namespace

std::string_view to_string(PulseInputKind kind) {
  switch (kind) {
    case PulseInputKind::SingleChannel:
      return "single channel";
    case PulseInputKind::Quadrature:
      return "quadrature";
  }
  return "unknown";
}

Result<PulseCounterConfig> PulseCounterConfig::make(const PulseCounterConfig& c) {
  if (!std::isfinite(c.min_spacing_s) || c.min_spacing_s < 0.0 || c.min_spacing_s > 1.0) {
    return fail("min_spacing_s must be 0 to 1 s");
  }
  return c;
}

void PulseCounter::set_drive(DriveDirection direction, double now_s) {
  // Stopped changes nothing: the motor coasts on in the direction it last turned.
  if (direction == DriveDirection::Stopped || direction == direction_) return;
  previous_direction_ = direction_;
  direction_ = direction;
  direction_since_s_ = std::isfinite(now_s) ? now_s : direction_since_s_;
}

DriveDirection PulseCounter::direction_at(double at_s) const {
  return at_s < direction_since_s_ ? previous_direction_ : direction_;
}

bool PulseCounter::accept_time(double at_s) {
  if (!std::isfinite(at_s) || (last_seen_s_ && at_s < *last_seen_s_)) {
    ++errors_;
    return false;
  }
  last_seen_s_ = at_s;
  return true;
}

void PulseCounter::on_pulse(double at_s) {
  if (!takes_pulses(config_.kind)) {
    ++errors_;
    return;
  }
  if (!accept_time(at_s)) return;
  if (last_accepted_pulse_s_ && at_s - *last_accepted_pulse_s_ < config_.min_spacing_s) {
    ++bounces_;
    return;
  }
  last_accepted_pulse_s_ = at_s;
  switch (direction_at(at_s)) {
    case DriveDirection::Stopped:
      ++ambiguous_;
      return;
    case DriveDirection::Forward:
      ++count_;
      break;
    case DriveDirection::Reverse:
      --count_;
      break;
  }
  last_edge_s_ = at_s;
}

void PulseCounter::on_quadrature_edge(QuadratureChannel channel, bool high, double at_s) {
  if (takes_pulses(config_.kind)) {
    ++errors_;
    return;
  }
  if (!accept_time(at_s)) return;
  bool& level = channel == QuadratureChannel::A ? a_high_ : b_high_;
  if (level == high) {
    ++errors_;  // the opposite edge was lost: the position moved two steps, or none
    return;
  }
  level = high;
  // The Gray sequence 00 → 10 → 11 → 01 → 00 (A leads B) is forward: after a forward edge of
  // A the channels differ, after a forward edge of B they agree.
  const bool forward = channel == QuadratureChannel::A ? a_high_ != b_high_ : a_high_ == b_high_;
  count_ += forward != config_.reversed ? 1 : -1;
  last_edge_s_ = at_s;
}

void PulseCounter::set_quadrature_levels(bool a_high, bool b_high) {
  a_high_ = a_high;
  b_high_ = b_high;
}

}  // namespace azt::control
