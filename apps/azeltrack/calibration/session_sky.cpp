#include "calibration/session_sky.hpp"

#include <algorithm>
#include <memory>

#include "calibration/calibration_sources.hpp"
#include "station/sky_follower.hpp"

namespace azt::app {
namespace {

/// An estimate not made (no dish given) does not hold a source back: the planner takes it.
constexpr double kUnestimatedSnrDb = 99.0;

calibration::SiteLimits limits_of(const control::StationSetup& station) {
  calibration::SiteLimits limits;
  limits.min_el_deg = std::max(limits.min_el_deg, station.el_range.min_deg);
  limits.max_el_deg = std::min(limits.max_el_deg, station.el_range.max_deg);
  limits.az_range = station.az_range;
  return limits;
}

}  // namespace

Result<SessionSky> session_sky(const CalibrationRequest& request, const astro::Ephemeris& ephemeris,
                               const SkyConfig& sky, const DishConfig& dish,
                               const control::StationSetup& station) {
  auto followers = std::make_shared<std::vector<SkyFollower>>();
  std::vector<astro::Target> targets;
  followers->reserve(request.sources.size());
  for (const std::string& name : request.sources) {
    const auto target = find_sky_target(sky, name);
    if (!target)
      return fail("sources: no source \"" + name + "\" here (GET /api/calibration/sources)");
    targets.push_back(*target);
    followers->emplace_back(ephemeris, sky);
    followers->back().follow(*target);
  }
  const auto offers = offer_sources(targets, dish, sky.settings.freq_mhz,
                                    request.spec.beamwidth_deg, request.timing.dwell_s);
  SessionSky out;
  for (const SourceOffer& o : offers) {
    if (!o.worth) return fail("sources: " + o.name + ": " + o.why);
    out.sources.push_back({o.name, o.snr_db.value_or(kUnestimatedSnrDb), o.size_deg, o.sun});
  }
  out.at_unix = [followers](std::size_t i, double unix_s) -> std::optional<control::AzEl> {
    if (i >= followers->size()) return std::nullopt;
    const auto fix = (*followers)[i].at(unix_s);
    if (!fix) return std::nullopt;
    return fix->position;
  };
  out.limits = limits_of(station);
  return out;
}

}  // namespace azt::app
