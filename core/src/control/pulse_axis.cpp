#include "azt/control/pulse_axis.hpp"

#include <string>

namespace azt::control {
namespace {

DriveDirection direction_of(double duty) {
  if (duty > 0.0) return DriveDirection::Forward;
  if (duty < 0.0) return DriveDirection::Reverse;
  return DriveDirection::Stopped;
}

}  // namespace

PulseAxis::PulseAxis(const PulseCounter& counter, const Homing& homing, const PulseScale& scale,
                     bool home_at_start)
    : counter_(counter),
      homing_(homing),
      scale_(scale),
      home_at_start_(home_at_start),
      nominal_deg_per_count_(scale.deg_per_count(0)) {}

Result<PulseAxis> PulseAxis::make(const PulseAxisConfig& config) {
  auto counter = PulseCounterConfig::make(config.counter);
  if (!counter) return fail("pulse counter: " + counter.error().message);
  auto homing = HomingConfig::make(config.homing);
  if (!homing) return fail("homing: " + homing.error().message);
  std::optional<ActuatorGeometry> geometry;
  if (config.geometry) {
    auto g = ActuatorGeometry::make(*config.geometry);
    if (!g) return fail("actuator geometry: " + g.error().message);
    geometry = *g;
  }
  auto scale = PulseScale::make(config.scale, geometry);
  if (!scale) return fail("pulse scale: " + scale.error().message);
  return PulseAxis(PulseCounter(*counter), Homing(*homing), *scale, config.home_at_start);
}

void PulseAxis::start_homing(double now_s, bool home_closed) {
  homing_.start(now_s, counter_.count(), home_closed);
}

void PulseAxis::on_edges(std::span<const ports::PulseEdge> edges) {
  for (const auto& e : edges) {
    switch (e.line) {
      case ports::PulseLine::Pulse:
        // One pulse per closure: the opening edge of the same pulse is not another step.
        if (e.high) counter_.on_pulse(e.at_s);
        break;
      case ports::PulseLine::QuadratureA:
        counter_.on_quadrature_edge(QuadratureChannel::A, e.high, e.at_s);
        break;
      case ports::PulseLine::QuadratureB:
        counter_.on_quadrature_edge(QuadratureChannel::B, e.high, e.at_s);
        break;
      case ports::PulseLine::Home:
        homing_.on_switch(e.high, e.at_s, counter_.count());
        break;
    }
  }
}

std::optional<double> PulseAxis::homing_duty(double now_s) {
  if (!homing_.active()) return std::nullopt;
  const double duty = homing_.update(now_s, counter_.count());
  if (!homing_.active()) return std::nullopt;
  return duty;
}

void PulseAxis::set_drive(double duty, double now_s) {
  counter_.set_drive(direction_of(duty), now_s);
}

Result<double> PulseAxis::position_deg(double origin_deg) const {
  if (auto from_home = homing_.counts_from_home(counter_.count())) {
    auto angle = scale_.angle_deg(*from_home);
    if (!angle) return fail("pulse count: " + angle.error().message);
    return *angle;
  }
  return origin_deg + static_cast<double>(counter_.count()) * nominal_deg_per_count_;
}

}  // namespace azt::control
