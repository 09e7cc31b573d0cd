#include "azt/track/satellite_pass_track.hpp"

#include <cmath>

namespace azt::track {

Result<std::vector<SkyPoint>> sample_pass(const orbit::Satellite& sat,
                                          const astro::UtcInstant& from, const orbit::Pass& pass,
                                          double dut1_s, const astro::Observer& site,
                                          double time_offset_s) {
  std::vector<SkyPoint> sky;
  const auto seconds = static_cast<long>(std::floor(pass.los_s - pass.aos_s));
  for (long i = 0; i <= seconds; ++i) {
    const double t = pass.aos_s + static_cast<double>(i);
    auto l = orbit::look(sat, astro::utc_plus(from, t), dut1_s, site);
    if (!l) return l.error();
    sky.push_back({time_offset_s + t, l->az_deg, l->el_deg});
  }
  return sky;
}

}  // namespace azt::track
