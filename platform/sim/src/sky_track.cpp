#include "azt/sim/sky_track.hpp"

#include <cmath>
#include <unordered_map>

namespace azt::sim {
namespace {

using control::AzEl;

class SkyNodes {
 public:
  explicit SkyNodes(SkyTrackSetup setup) : setup_(std::move(setup)) {}

  std::optional<AzEl> at(double t_s) {
    const double k = std::floor(t_s);
    const auto a = node(static_cast<std::int64_t>(k));
    const auto b = node(static_cast<std::int64_t>(k) + 1);
    if (!a || !b) return std::nullopt;
    const double f = t_s - k;
    const double daz = control::wrap_360(b->az_deg - a->az_deg + 180.0) - 180.0;
    return AzEl{control::wrap_360(a->az_deg + f * daz), a->el_deg + f * (b->el_deg - a->el_deg)};
  }

 private:
  std::optional<AzEl> node(std::int64_t second) {
    if (auto it = cache_.find(second); it != cache_.end()) return it->second;
    if (cache_.size() > kMaxCached) cache_.clear();  // a run walks forward: old nodes are done
    const auto value = compute(second);
    cache_.emplace(second, value);
    return value;
  }

  [[nodiscard]] std::optional<AzEl> compute(std::int64_t second) const {
    astro::UtcInstant utc = setup_.start;
    utc.jd.jd2 += static_cast<double>(second) / 86400.0;
    auto time = astro::make_time_scales(utc, setup_.dut1_s, *setup_.leap_table);
    if (!time) return std::nullopt;
    auto epoch = astro::make_epoch(*setup_.ephemeris, *time);
    if (!epoch) return std::nullopt;
    const auto station = astro::make_station(*epoch, setup_.observer);
    auto seen =
        astro::observe(setup_.target, *setup_.ephemeris, *epoch, station, setup_.atmosphere);
    if (!seen) return std::nullopt;
    return AzEl{seen->place.az_deg, seen->el_deg};
  }

  static constexpr std::size_t kMaxCached = 64;
  SkyTrackSetup setup_;
  std::unordered_map<std::int64_t, std::optional<AzEl>> cache_;
};

}  // namespace

SkyTrack make_sky_track(const SkyTrackSetup& setup) {
  auto nodes = std::make_shared<SkyNodes>(setup);
  return [nodes](double t_s) { return nodes->at(t_s); };
}

}  // namespace azt::sim
