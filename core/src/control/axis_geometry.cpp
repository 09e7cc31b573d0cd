#include "azt/control/axis_geometry.hpp"

#include <cmath>

namespace azt::control {

Result<AzimuthRange> AzimuthRange::make(double min_deg, double max_deg) {
  if (!std::isfinite(min_deg) || !std::isfinite(max_deg)) {
    return fail("azimuth range limits must be finite");
  }
  const double span = max_deg - min_deg;
  if (span < 360.0 || span > 720.0) {
    return fail("azimuth range must span 360 to 720 degrees (min_deg < max_deg)");
  }
  return AzimuthRange{min_deg, max_deg};
}

Result<ElevationRange> ElevationRange::make(double min_deg, double max_deg) {
  if (!std::isfinite(min_deg) || !std::isfinite(max_deg) || min_deg < -10.0 || max_deg > 180.0 ||
      min_deg >= max_deg) {
    return fail("elevation range must satisfy -10 <= min_deg < max_deg <= 180");
  }
  return ElevationRange{min_deg, max_deg};
}

double wrap_360(double deg) {
  double w = std::fmod(deg, 360.0);
  if (w < 0.0) w += 360.0;
  return w >= 360.0 ? 0.0 : w;
}

double plan_azimuth(double current_mount_deg, double target_sky_deg, const AzimuthRange& range) {
  // Candidates az + k·360 inside the range; at most three exist for a 720° range.
  const double base = wrap_360(target_sky_deg);
  const double first = base + 360.0 * std::ceil((range.min_deg - base) / 360.0);
  double best = first;
  for (int k = 1; first + 360.0 * k <= range.max_deg; ++k) {
    const double candidate = first + 360.0 * k;
    if (std::fabs(candidate - current_mount_deg) < std::fabs(best - current_mount_deg)) {
      best = candidate;
    }
  }
  return best;
}

std::optional<double> plan_elevation(double target_el_deg, const ElevationRange& range) {
  if (!std::isfinite(target_el_deg) || target_el_deg < range.min_deg ||
      target_el_deg > range.max_deg) {
    return std::nullopt;
  }
  return target_el_deg;
}

}  // namespace azt::control
