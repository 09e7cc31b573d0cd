#include "azt/astro/sky_snapshot.hpp"

namespace azt::astro {

Result<SkySnapshot> SkySnapshot::at(const Ephemeris& ephemeris, const SkySite& site,
                                    const TimeScales& time) {
  auto epoch = make_epoch(ephemeris, time);
  if (!epoch) return epoch.error();
  return SkySnapshot(ephemeris, site, *epoch);
}

SkySnapshot::SkySnapshot(const Ephemeris& ephemeris, const SkySite& site, const Epoch& epoch)
    : ephemeris_(&ephemeris),
      site_(site),
      epoch_(epoch),
      station_(make_station(epoch_, site.observer)) {
  if (site.dx) dx_station_ = make_station(epoch_, *site.dx);
}

Result<SkySnapshot> SkySnapshot::later(double seconds) const {
  constexpr double kSecondsPerDay = 86400.0;
  TimeScales t = epoch_.time;
  t.utc = utc_plus(t.utc, seconds);
  t.tt.jd2 += seconds / kSecondsPerDay;
  t.ut1.jd2 += seconds / kSecondsPerDay;
  return at(*ephemeris_, site_, t);
}

Result<TargetReport> SkySnapshot::observe(const Target& target) const {
  auto obs = astro::observe(target, *ephemeris_, epoch_, station_, site_.atmosphere);
  if (!obs) return obs.error();
  TargetReport report{target, *obs, std::nullopt, std::nullopt};
  if (target.kind == Target::Kind::Moon && dx_station_) {
    auto dx = observe_moon(*ephemeris_, epoch_, *dx_station_);
    if (!dx) return dx.error();
    report.dx_range_rate_km_s = dx->range_rate_km_s;
    report.dx_place = *dx;
  }
  return report;
}

}  // namespace azt::astro
