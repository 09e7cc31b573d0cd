#include "station/simulated_power.hpp"

#include <cmath>
#include <utility>

namespace azt::app {
namespace {

/// A place that could not be observed (a spacecraft outside its table, say).
constexpr double kNowhereDeg = -1000.0;

}  // namespace

SimulatedPower::SimulatedPower(SimulatedPowerParts parts)
    : p_(std::move(parts)), emitters_(sky_emitters(p_.receiver)), receiver_(p_.receiver.receiver) {}

bool SimulatedPower::observe_second(double second, std::vector<control::AzEl>& places) const {
  const auto snapshot = p_.sky_at(second);
  if (!snapshot) return false;
  places.assign(emitters_.size(), control::AzEl{0.0, kNowhereDeg});
  for (std::size_t i = 0; i < emitters_.size(); ++i) {
    if (const auto r = snapshot->observe(emitters_[i].target)) {
      places[i] = control::AzEl{r->observation.place.az_deg, r->observation.el_deg};
    }
  }
  return true;
}

std::optional<std::vector<sim::RadioEmitter>> SimulatedPower::sky(double unix_s) {
  const double second = std::floor(unix_s);
  if (second != second_) {
    const bool moved_on = second == second_ + 1.0 && !next_.empty();
    if (moved_on) {
      now_ = std::move(next_);
    } else if (!observe_second(second, now_)) {
      return std::nullopt;
    }
    if (!observe_second(second + 1.0, next_)) return std::nullopt;
    second_ = second;
  }
  const double f = unix_s - second_;
  std::vector<sim::RadioEmitter> out;
  for (std::size_t i = 0; i < emitters_.size(); ++i) {
    if (now_[i].el_deg <= kNowhereDeg || next_[i].el_deg <= kNowhereDeg) continue;
    const double az = now_[i].az_deg + f * std::remainder(next_[i].az_deg - now_[i].az_deg, 360.0);
    const double el = now_[i].el_deg + f * (next_[i].el_deg - now_[i].el_deg);
    out.push_back({control::AzEl{az, el}, emitters_[i].peak_k, emitters_[i].size_deg});
  }
  return out;
}

std::optional<SimulatedPower::Heard> SimulatedPower::heard(double unix_s) {
  const auto shafts = p_.shafts_deg();
  auto emitters = sky(unix_s);
  if (!shafts || !emitters) return std::nullopt;
  return Heard{calibration::beam_on_sky(*shafts, p_.mount_errors), std::move(*emitters)};
}

std::optional<double> SimulatedPower::read_db(double unix_s) {
  const auto h = heard(unix_s);
  if (!h) return std::nullopt;
  return receiver_.read_db(h->beam, h->emitters);
}

std::optional<double> SimulatedPower::expected_db(double unix_s) {
  const auto h = heard(unix_s);
  if (!h) return std::nullopt;
  return receiver_.expected_db(h->beam, h->emitters);
}

}  // namespace azt::app
