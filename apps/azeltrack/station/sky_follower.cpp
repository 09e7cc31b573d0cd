#include "station/sky_follower.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "azt/control/axis_geometry.hpp"
#include "common/sky_report.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

/// Unix seconds to a UTC Julian date (the day count is exact in two parts).
astro::UtcInstant utc_from_unix(double unix_s) {
  const double days = std::floor(unix_s / 86400.0);
  return astro::UtcInstant{
      astro::JulianDate{2440587.5 + days, (unix_s - days * 86400.0) / 86400.0}};
}

}  // namespace

std::optional<astro::Target> SkyFollower::find(const std::string& name) const {
  return find_sky_target(station_, name);
}

void SkyFollower::refollow() {
  if (!target_) return;
  const auto again = find(target_->name);
  follow(again ? *again : *target_);
}

void SkyFollower::follow(const astro::Target& target) {
  target_ = target;
  t0_ = -1.0;
}

std::optional<control::AzEl> SkyFollower::compute(double utc_unix_s) {
  const auto snapshot = sky_snapshot(ephemeris_, station_.settings, utc_from_unix(utc_unix_s));
  const auto r = snapshot ? snapshot->observe(*target_) : snapshot.error();
  if (!r) {
    last_error_ = r.error().message;
    return std::nullopt;
  }
  return control::AzEl{r->observation.place.az_deg, r->observation.el_deg};
}

std::optional<SkyFix> SkyFollower::at(double utc_unix_s) {
  if (!target_) return std::nullopt;
  const double whole = std::floor(utc_unix_s);
  if (whole != t0_) {
    t0_ = whole;
    p0_ = compute(whole);
    p1_ = compute(whole + 1.0);
  }
  if (!p0_ || !p1_) return std::nullopt;
  const double f = utc_unix_s - whole;
  const double daz = control::wrap_360(p1_->az_deg - p0_->az_deg + 180.0) - 180.0;
  const double del = p1_->el_deg - p0_->el_deg;
  return SkyFix{{control::wrap_360(p0_->az_deg + f * daz), p0_->el_deg + f * del}, {daz, del}};
}

}  // namespace azt::app
