#include "azt/sim/sky_bench.hpp"

#include <cmath>

namespace azt::sim {

using control::AzEl;

SkyBench::SkyBench(const CalibrationSimSetup& setup)
    : setup_(setup),
      loop_(setup.station, nullptr),
      receiver_(setup.receiver),
      next_reading_s_(1.0 / setup.receiver.rate_hz) {}

void SkyBench::step(const std::optional<AzEl>& demand, const AzEl& rate) {
  loop_.tick(t_, demand, rate);
  loop_.collect_faults(faults_, t_);
  t_ += setup_.station.station.tick_s;
}

void SkyBench::hold(const AzEl& demand) { step(demand, AzEl{}); }

void SkyBench::follow(const CalibrationSource& source, const calibration::SkyOffset& offset) {
  const auto here = source.track(t_);
  if (!here) {
    step(std::nullopt, AzEl{});
    return;
  }
  const AzEl demand = calibration::apply_offset(*here, offset);
  AzEl rate{};
  if (const auto ahead = source.track(t_ + 1.0)) {
    const AzEl next = calibration::apply_offset(*ahead, offset);
    rate = {std::remainder(next.az_deg - demand.az_deg, 360.0), next.el_deg - demand.el_deg};
  }
  step(demand, rate);
}

bool SkyBench::driving() const {
  return loop_.station().az().moving || loop_.station().el().moving;
}

std::optional<AzEl> SkyBench::encoders() const { return loop_.station().encoder_reading(); }

std::optional<calibration::SkyOffset> SkyBench::pointed(const CalibrationSource& source) const {
  const auto src = source.track(t_);
  const auto believed = loop_.station().sky_position(t_);
  if (!src || !believed) return std::nullopt;
  return calibration::offset_between(*src, *believed);
}

std::optional<calibration::SkyOffset> SkyBench::source_from_beam(
    const CalibrationSource& source) const {
  const auto src = source.track(t_);
  const auto believed = loop_.station().sky_position(t_);
  if (!src || !believed) return std::nullopt;
  return calibration::offset_between(*believed, *src);
}

std::optional<double> SkyBench::reading() {
  if (t_ < next_reading_s_) return std::nullopt;
  next_reading_s_ += 1.0 / setup_.receiver.rate_hz;
  return receiver_.read_db(true_beam(), sky_at(t_));
}

AzEl SkyBench::true_beam() const {
  const auto& offsets = setup_.station.station.corrections.offsets;
  const AzEl mount{loop_.az_plant().shaft_deg() + offsets.az_deg,
                   loop_.el_plant().shaft_deg() + offsets.el_deg};
  return calibration::beam_on_sky(mount, setup_.station.plant.pointing_errors);
}

std::vector<RadioEmitter> SkyBench::sky_at(double t_s) const {
  std::vector<RadioEmitter> out;
  for (const CalibrationSource& s : setup_.sources) {
    if (const auto at = s.track(t_s)) out.push_back({*at, s.peak_k, s.size_deg});
  }
  return out;
}

}  // namespace azt::sim
