#include "azt/sim/pol_track.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "azt/astro/sky.hpp"
#include "azt/eme/polarisation.hpp"

namespace azt::sim {
namespace {

constexpr double kNodeS = 10.0;

class DpolNodes {
 public:
  explicit DpolNodes(const PolTrackSetup& setup) : setup_(setup) {}

  std::optional<double> at(double t_s) {
    const double k = std::floor(t_s / kNodeS);
    const auto a = node(static_cast<std::int64_t>(k));
    const auto b = node(static_cast<std::int64_t>(k) + 1);
    if (!a || !b) return std::nullopt;
    // Across the fold at ±90 the shorter way round (a linear polarisation repeats every 180°).
    const double step = std::remainder(*b - *a, 180.0);
    return control::fold_linear_deg(*a + (t_s / kNodeS - k) * step);
  }

 private:
  std::optional<double> node(std::int64_t index) {
    if (auto it = cache_.find(index); it != cache_.end()) return it->second;
    if (cache_.size() > kMaxCached) cache_.clear();  // a run walks forward: old nodes are done
    const auto value = compute(static_cast<double>(index) * kNodeS);
    cache_.emplace(index, value);
    return value;
  }

  [[nodiscard]] std::optional<double> compute(double t_s) const {
    astro::UtcInstant utc = setup_.start;
    utc.jd.jd2 += t_s / 86400.0;
    auto time = astro::make_time_scales(utc, setup_.dut1_s, *setup_.leap_table);
    if (!time) return std::nullopt;
    auto epoch = astro::make_epoch(*setup_.ephemeris, *time);
    if (!epoch) return std::nullopt;
    const auto own =
        astro::observe_moon(*setup_.ephemeris, *epoch, astro::make_station(*epoch, setup_.own));
    const auto dx =
        astro::observe_moon(*setup_.ephemeris, *epoch, astro::make_station(*epoch, *setup_.dx));
    if (!own || !dx) return std::nullopt;
    // As moon_conditions does for the EME data: the airless elevation, as WSJT-X's.
    return eme::dpol_deg(
        eme::parallactic_angle_deg(setup_.own.lat_deg, own->az_deg, own->el_geometric_deg),
        eme::parallactic_angle_deg(setup_.dx->lat_deg, dx->az_deg, dx->el_geometric_deg));
  }

  static constexpr std::size_t kMaxCached = 64;
  PolTrackSetup setup_;
  std::unordered_map<std::int64_t, std::optional<double>> cache_;
};

}  // namespace

bool transmitting_at(double t_s, double ptt_period_s) {
  if (!(ptt_period_s > 0.0)) return false;
  return static_cast<std::int64_t>(std::floor(t_s / ptt_period_s)) % 2 != 0;
}

std::function<std::optional<double>(double t_s)> make_dpol_track(const PolTrackSetup& setup) {
  if (!setup.dx) return [](double) { return std::optional<double>{}; };
  auto nodes = std::make_shared<DpolNodes>(setup);
  return [nodes](double t_s) { return nodes->at(t_s); };
}

PolTrack make_pol_track(const PolTrackSetup& setup) {
  auto dpol = make_dpol_track(setup);
  return [dpol, settings = setup.settings, period = setup.ptt_period_s](double t_s) {
    control::PolInputs in;
    in.spatial_offset_deg = dpol(t_s);
    in.transmitting = transmitting_at(t_s, period);
    return control::pol_feed_deg(settings, in);
  };
}

}  // namespace azt::sim
