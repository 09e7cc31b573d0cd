#include "azt/orbit/satellite.hpp"

namespace azt::orbit {

double element_age_days(const Elements& e, const astro::UtcInstant& utc) {
  return (utc.jd.jd1 - e.epoch_jd) + (utc.jd.jd2 - e.epoch_jd_frac);
}

Result<LookAngles> look(const Satellite& sat, const astro::UtcInstant& utc, double dut1_s,
                        const astro::Observer& site) {
  auto state = sat.sgp4.at_jd(utc.jd.jd1, utc.jd.jd2);
  if (!state) return fail(sat.elements.label() + ": " + state.error().message);
  const astro::JulianDate ut1{utc.jd.jd1, utc.jd.jd2 + dut1_s / 86400.0};
  return look_angles(state->r_km, state->v_km_s, ut1, site);
}

Result<std::vector<Pass>> find_satellite_passes(const Satellite& sat, const astro::UtcInstant& from,
                                                double hours, const HorizonMask& mask,
                                                double dut1_s, const astro::Observer& site) {
  const PassSearch search = orbit_pass_search(sat.elements.mean_motion_rev_day,
                                              sat.elements.eccentricity, 0.0, hours * 3600.0, mask);
  const LookFunction at = [&](double t) {
    return look(sat, astro::utc_plus(from, t), dut1_s, site);
  };
  return find_passes(at, search);
}

}  // namespace azt::orbit
