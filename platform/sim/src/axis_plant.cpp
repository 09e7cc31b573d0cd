#include "azt/sim/axis_plant.hpp"
#include "azt/proto/hub_frame.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "azt/control/axis_geometry.hpp"

namespace azt::sim {
namespace {

bool all_finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

Result<AxisParams> AxisParams::validate() const {
  if (!all_finite({max_rate_deg_s, time_constant_s, backlash_deg, stiction_duty, start_deg, min_deg,
                   max_deg})) {
    return fail("plant parameters must be finite");
  }
  if (max_rate_deg_s <= 0.0) return fail("max_rate_deg_s must be positive");
  if (time_constant_s <= 0.0) return fail("time_constant_s must be positive");
  if (backlash_deg < 0.0) return fail("backlash_deg must not be negative");
  if (stiction_duty < 0.0 || stiction_duty >= 1.0) return fail("stiction_duty must be in [0, 1)");
  // The EncoderHub frame carries 9 to 16 bits per encoder (seed 000, "Encoder Hub Data Format").
  if (encoder_bits < 9 || encoder_bits > 16) return fail("encoder_bits must be 9 to 16");
  if (min_deg >= max_deg) return fail("min_deg must be below max_deg");
  if (start_deg < min_deg || start_deg > max_deg) {
    return fail("start_deg must be within min_deg..max_deg");
  }
  return *this;
}

std::string_view to_string(AxisFaultKind kind) {
  switch (kind) {
    case AxisFaultKind::FrozenShaft:
      return "frozen shaft";
    case AxisFaultKind::ReversedMotor:
      return "reversed motor";
    case AxisFaultKind::EncoderOffset:
      return "encoder offset";
    case AxisFaultKind::EncoderGlitch:
      return "encoder glitch";
  }
  return "unknown";
}

AxisPlant::AxisPlant(const AxisParams& params)
    : params_(params), motor_deg_(params.start_deg), shaft_deg_(params.start_deg) {}

Result<AxisPlant> AxisPlant::make(const AxisParams& params) {
  const auto ok = params.validate();
  if (!ok) return ok.error();
  return AxisPlant(params);
}

double AxisPlant::commanded_rate_deg_s(double duty) const {
  const double s = params_.stiction_duty;
  const double magnitude = std::fabs(duty);
  if (magnitude <= s) return 0.0;
  return std::copysign(params_.max_rate_deg_s * (magnitude - s) / (1.0 - s), duty);
}

double AxisPlant::decay_for(double dt_s) {
  if (dt_s != cached_dt_s_) {
    cached_dt_s_ = dt_s;
    cached_decay_ = std::exp(-dt_s / params_.time_constant_s);
  }
  return cached_decay_;
}

void AxisPlant::step(double duty, double dt_s) {
  glitch_counts_ = 0;
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) return;
  double d = std::isfinite(duty) ? std::clamp(duty, -1.0, 1.0) : 0.0;
  if (reversed_) d = -d;
  const double target = commanded_rate_deg_s(d);
  const double decay = decay_for(dt_s);
  const double excess = motor_rate_deg_s_ - target;  // decays as e^(−t/τ)
  // ∫₀^dt (ω_c + excess·e^(−t/τ)) dt = ω_c·dt + excess·τ·(1 − e^(−dt/τ))
  motor_deg_ += target * dt_s + excess * params_.time_constant_s * (1.0 - decay);
  motor_rate_deg_s_ = target + excess * decay;
  if (frozen_) return;  // the motor runs free of the held shaft
  apply_stops();
  apply_backlash();
}

void AxisPlant::apply_stops() {
  const double half_play = params_.backlash_deg / 2.0;
  const double upper = params_.max_deg + half_play;
  const double lower = params_.min_deg - half_play;
  if (motor_deg_ > upper) {
    motor_deg_ = upper;
    motor_rate_deg_s_ = std::min(motor_rate_deg_s_, 0.0);
  } else if (motor_deg_ < lower) {
    motor_deg_ = lower;
    motor_rate_deg_s_ = std::max(motor_rate_deg_s_, 0.0);
  }
}

void AxisPlant::apply_backlash() {
  const double half_play = params_.backlash_deg / 2.0;
  if (motor_deg_ - shaft_deg_ > half_play) {
    shaft_deg_ = motor_deg_ - half_play;
  } else if (shaft_deg_ - motor_deg_ > half_play) {
    shaft_deg_ = motor_deg_ + half_play;
  }
  // Exactly on the stop (max + b/2 − b/2 need not round back to max).
  shaft_deg_ = std::clamp(shaft_deg_, params_.min_deg, params_.max_deg);
}

std::uint16_t AxisPlant::encoder_raw() const {
  const std::int64_t modulus = std::int64_t{1} << params_.encoder_bits;
  // Scaling by 2^bits is exact, so readings change exactly at multiples of the LSB.
  const double counts =
      std::floor(control::wrap_360(shaft_deg_) / 360.0 * static_cast<double>(modulus));
  std::int64_t raw = static_cast<std::int64_t>(counts) + offset_counts_ + glitch_counts_;
  raw %= modulus;
  if (raw < 0) raw += modulus;
  return static_cast<std::uint16_t>(raw);
}

double AxisPlant::lsb_deg() const { return proto::hub_resolution_deg(params_.encoder_bits); }

void AxisPlant::inject(const AxisFault& fault) {
  switch (fault.kind) {
    case AxisFaultKind::FrozenShaft:
      frozen_ = true;
      break;
    case AxisFaultKind::ReversedMotor:
      reversed_ = true;
      break;
    case AxisFaultKind::EncoderOffset:
      offset_counts_ = fault.counts;
      break;
    case AxisFaultKind::EncoderGlitch:
      glitch_counts_ = fault.counts;
      break;
  }
}

void AxisPlant::clear(AxisFaultKind kind) {
  switch (kind) {
    case AxisFaultKind::FrozenShaft:
      if (frozen_) motor_deg_ = shaft_deg_;
      frozen_ = false;
      break;
    case AxisFaultKind::ReversedMotor:
      reversed_ = false;
      break;
    case AxisFaultKind::EncoderOffset:
      offset_counts_ = 0;
      break;
    case AxisFaultKind::EncoderGlitch:
      glitch_counts_ = 0;
      break;
  }
}

void AxisPlant::clear_faults() {
  for (const auto kind : {AxisFaultKind::FrozenShaft, AxisFaultKind::ReversedMotor,
                          AxisFaultKind::EncoderOffset, AxisFaultKind::EncoderGlitch}) {
    clear(kind);
  }
}

bool AxisPlant::has_fault(AxisFaultKind kind) const {
  switch (kind) {
    case AxisFaultKind::FrozenShaft:
      return frozen_;
    case AxisFaultKind::ReversedMotor:
      return reversed_;
    case AxisFaultKind::EncoderOffset:
      return offset_counts_ != 0;
    case AxisFaultKind::EncoderGlitch:
      return glitch_counts_ != 0;
  }
  return false;
}

}  // namespace azt::sim
