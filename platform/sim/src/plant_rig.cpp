#include "azt/sim/plant_rig.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace azt::sim {

PlantRig::PlantRig(const PlantSetup& plant, std::unique_ptr<SimulatedHub> hub)
    : faults_(plant.faults), plants_(plant.az, plant.el), hub_(std::move(hub)) {
  if (plant.pol) pol_.emplace(*plant.pol);
  for (std::size_t i = 0; i < 2; ++i) {
    if (plant.brakes.at(i)) brakes_.at(i).emplace(*plant.brakes.at(i));
    if (plant.thermal.at(i)) thermal_.at(i).emplace(*plant.thermal.at(i));
  }
  if (plant.el_actuator) {
    el_dish_.emplace(plant.el_actuator->dish);
    if (const SimActuatorReed* reed = plant.el_actuator->reed()) {
      el_counted_ = true;
      if (reed->drop_pulse_at_s) el_dish_->drop_pulse_after(*reed->drop_pulse_at_s);
    }
    plants_.el_follows(el_dish_->angle_deg(), 0.0);
  }
}

void PlantRig::step_el_dish(double duty, double step_s, double end_s) {
  std::vector<ActuatorEvent> events = el_dish_->step(duty, step_s);
  // A pot reads the length: with no reed to take them, the edges would only pile up.
  if (!el_counted_) events.clear();
  for (const ActuatorEvent& e : events) {
    // On the loop's clock: the dish's own clock skips the time a late tick's cap leaves out.
    const double at_s = end_s - (el_dish_->now_s() - e.at_s);
    switch (e.kind) {
      case ActuatorEventKind::Pulse:
        el_edges_.push_back({ports::PulseLine::Pulse, true, at_s});
        break;
      case ActuatorEventKind::HomeClosed:
        el_edges_.push_back({ports::PulseLine::Home, true, at_s});
        break;
      case ActuatorEventKind::HomeOpened:
        el_edges_.push_back({ports::PulseLine::Home, false, at_s});
        break;
    }
  }
  const double rate_deg_s =
      el_dish_->rate_mm_s() * el_dish_->geometry().deg_per_mm(el_dish_->length_mm());
  plants_.el_follows(el_dish_->angle_deg(), rate_deg_s);
}

std::optional<double> PlantRig::motor_temperature_c(std::size_t axis, double now_s) {
  advance(now_s);
  if (!thermal_.at(axis)) return std::nullopt;
  return thermal_.at(axis)->temperature_c();
}

std::optional<HubArrival> PlantRig::frame_for(std::size_t axis, double now_s) {
  advance(now_s);
  if (!std::exchange(fresh_.at(axis), false)) return std::nullopt;
  return frame_;
}

std::optional<std::uint16_t> PlantRig::pol_raw(double now_s) {
  advance(now_s);
  if (!pol_) return std::nullopt;
  return pol_->encoder_raw();
}

std::optional<double> PlantRig::el_length_mm(double now_s) {
  advance(now_s);
  if (!el_dish_) return std::nullopt;
  return el_dish_->length_mm();
}

void PlantRig::advance(double now_s) {
  if (last_s_ && *last_s_ == now_s) return;
  if (!first_s_) first_s_ = now_s;
  const double dt = last_s_ ? std::clamp(now_s - *last_s_, 0.0, 1.0) : 0.0;
  const double from_s = now_s - dt - *first_s_;
  last_s_ = now_s;
  const double step_s = hub_->step_s();
  const auto steps = static_cast<int>(std::ceil(dt / step_s - 1e-9));
  for (int i = 0; i < steps; ++i) {
    const double step = std::min(step_s, dt - i * step_s);
    // The motor heats with its duty whether or not a brake lets the shaft turn.
    std::array<double, 2> shaft_duty = duty_;
    for (std::size_t a = 0; a < 2; ++a) {
      if (brakes_.at(a)) shaft_duty.at(a) = brakes_.at(a)->step(brake_on_.at(a), duty_.at(a), step);
      if (thermal_.at(a)) thermal_.at(a)->step(duty_.at(a), step);
    }
    plants_.step(shaft_duty[0], el_dish_ ? 0.0 : shaft_duty[1], step);
    if (el_dish_) step_el_dish(shaft_duty[1], step, now_s - dt + std::min(dt, (i + 1) * step_s));
    if (pol_) pol_->step(pol_duty_, step);
    faults_.inject_due(from_s + std::min(dt, (i + 1) * step_s), plants_);
    hub_->run(plants_, step);
  }
  faults_.inject_due(now_s - *first_s_, plants_);
  if (auto f = hub_->take_frame(plants_, now_s)) {
    frame_ = f;
    fresh_ = {true, true};
  }
}

}  // namespace azt::sim
