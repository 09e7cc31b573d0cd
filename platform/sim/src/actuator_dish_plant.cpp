#include "azt/sim/actuator_dish_plant.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace azt::sim {
namespace {

bool all_finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

std::string_view to_string(ActuatorEventKind kind) {
  switch (kind) {
    case ActuatorEventKind::Pulse:
      return "pulse";
    case ActuatorEventKind::HomeClosed:
      return "home switch closed";
    case ActuatorEventKind::HomeOpened:
      return "home switch opened";
  }
  return "unknown";
}

Result<ActuatorDishParams> ActuatorDishParams::validate() const {
  if (const auto g = control::ActuatorGeometryConfig::make(geometry); !g) return g.error();
  if (!all_finite({speed_mm_s, time_constant_s, stiction_duty, pulses_per_mm, pulse_phase,
                   home_switch_mm, start_mm})) {
    return fail("actuator plant parameters must be finite");
  }
  if (speed_mm_s <= 0.0) return fail("speed_mm_s must be positive");
  if (time_constant_s <= 0.0) return fail("time_constant_s must be positive");
  if (stiction_duty < 0.0 || stiction_duty >= 1.0) return fail("stiction_duty must be in [0, 1)");
  if (pulses_per_mm <= 0.0 || pulses_per_mm > 100.0)
    return fail("pulses_per_mm must be in (0, 100]");
  if (pulse_phase < 0.0 || pulse_phase >= 1.0) return fail("pulse_phase must be in [0, 1)");
  const auto within = [&](double mm) {
    return mm >= geometry.retracted_mm && mm <= geometry.extended_mm;
  };
  if (!within(home_switch_mm)) return fail("home_switch_mm must be within the stroke");
  if (!within(start_mm)) return fail("start_mm must be within the stroke");
  return *this;
}

ActuatorDishPlant::ActuatorDishPlant(const ActuatorDishParams& params)
    : params_(params), geometry_(params.geometry), length_mm_(params.start_mm) {}

Result<ActuatorDishPlant> ActuatorDishPlant::make(const ActuatorDishParams& params) {
  const auto ok = params.validate();
  if (!ok) return ok.error();
  return ActuatorDishPlant(params);
}

double ActuatorDishPlant::angle_deg() const { return geometry_.angle_deg(length_mm_).value(); }

double ActuatorDishPlant::commanded_rate_mm_s(double duty) const {
  const double s = params_.stiction_duty;
  const double magnitude = std::fabs(duty);
  if (magnitude <= s) return 0.0;
  return std::copysign(params_.speed_mm_s * (magnitude - s) / (1.0 - s), duty);
}

void ActuatorDishPlant::move(double duty, double dt_s) {
  const double target = commanded_rate_mm_s(duty);
  const double tau = params_.time_constant_s;
  const double decay = std::exp(-dt_s / tau);
  // The exact integral of ω(t) = ω_c + (ω0 − ω_c)·e^(−t/τ) over the step.
  length_mm_ += target * dt_s + (rate_mm_s_ - target) * tau * (1.0 - decay);
  rate_mm_s_ = target + (rate_mm_s_ - target) * decay;
  const auto& g = params_.geometry;
  if (length_mm_ <= g.retracted_mm) {
    length_mm_ = g.retracted_mm;
    rate_mm_s_ = std::max(rate_mm_s_, 0.0);
  } else if (length_mm_ >= g.extended_mm) {
    length_mm_ = g.extended_mm;
    rate_mm_s_ = std::min(rate_mm_s_, 0.0);
  }
}

double ActuatorDishPlant::crossing_s(double from_mm, double to_mm, double at_mm,
                                     double dt_s) const {
  return now_s_ + dt_s * (at_mm - from_mm) / (to_mm - from_mm);
}

void ActuatorDishPlant::add_pulses(double from_mm, double to_mm, double dt_s,
                                   std::vector<ActuatorEvent>& events) {
  // Pulse k sits where u = (L − retracted)·ppm − phase is the integer k.
  const auto u = [&](double mm) {
    return (mm - params_.geometry.retracted_mm) * params_.pulses_per_mm - params_.pulse_phase;
  };
  const auto k_from = static_cast<long long>(std::floor(u(from_mm)));
  const auto k_to = static_cast<long long>(std::floor(u(to_mm)));
  const long long first = to_mm > from_mm ? k_from + 1 : k_from;
  const long long last = to_mm > from_mm ? k_to : k_to + 1;
  const long long step = to_mm > from_mm ? 1 : -1;
  for (long long k = first; step > 0 ? k <= last : k >= last; k += step) {
    const double at_mm = params_.geometry.retracted_mm +
                         (static_cast<double>(k) + params_.pulse_phase) / params_.pulses_per_mm;
    const double at_s = crossing_s(from_mm, to_mm, at_mm, dt_s);
    if (drop_after_s_ && at_s >= *drop_after_s_) {
      drop_after_s_.reset();
      ++dropped_;
      continue;
    }
    ++emitted_;
    events.push_back({ActuatorEventKind::Pulse, at_s});
  }
}

void ActuatorDishPlant::add_switch_edge(double from_mm, double to_mm, double dt_s,
                                        std::vector<ActuatorEvent>& events) const {
  const double at_mm = params_.home_switch_mm;
  const bool was_closed = from_mm <= at_mm;
  const bool is_closed = to_mm <= at_mm;
  if (was_closed == is_closed) return;
  events.push_back({is_closed ? ActuatorEventKind::HomeClosed : ActuatorEventKind::HomeOpened,
                    crossing_s(from_mm, to_mm, at_mm, dt_s)});
}

std::vector<ActuatorEvent> ActuatorDishPlant::step(double duty, double dt_s) {
  std::vector<ActuatorEvent> events;
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) return events;
  const double from_mm = length_mm_;
  move(std::isfinite(duty) ? std::clamp(duty, -1.0, 1.0) : 0.0, dt_s);
  if (length_mm_ != from_mm) {
    add_pulses(from_mm, length_mm_, dt_s, events);
    add_switch_edge(from_mm, length_mm_, dt_s, events);
    std::stable_sort(
        events.begin(), events.end(),
        [](const ActuatorEvent& a, const ActuatorEvent& b) { return a.at_s < b.at_s; });
  }
  now_s_ += dt_s;
  return events;
}

}  // namespace azt::sim
