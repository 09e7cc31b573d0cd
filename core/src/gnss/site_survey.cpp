#include "azt/gnss/site_survey.hpp"

#include <cmath>

#include "azt/gnss/fix_range.hpp"

namespace azt::gnss {
namespace {

constexpr double kEarthRadiusM = 6371008.8;  // IUGG mean radius
constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxGapS = 5.0;  ///< a receiver silent longer than this breaks the run
constexpr double kSameSiteM = 1.0;

double radians(double deg) { return deg * kPi / 180.0; }

double square(double x) { return x * x; }

/// Longitude difference wrapped to [-180, 180].
double dlon_deg(double lon_deg, double ref_deg) { return std::remainder(lon_deg - ref_deg, 360.0); }

/// A longitude wrapped to (-180, 180].
double wrap_lon_deg(double lon_deg) {
  const double r = std::remainder(lon_deg, 360.0);  // [-180, 180]
  return r <= -180.0 ? r + 360.0 : r;
}

/// A 3D fix whose place is on the Earth: out-of-range coordinates are refused, never wrapped.
bool usable_3d(const GpsFix& fix) {
  return fix.mode == FixMode::Fix3d && fix.alt_m && !out_of_range(fix);
}

}  // namespace

double ground_distance_m(const Site& a, const Site& b) {
  const double dlat = radians(b.lat_deg - a.lat_deg);
  const double dlon = radians(dlon_deg(b.lon_deg, a.lon_deg));
  const double h = square(std::sin(dlat / 2.0)) + std::cos(radians(a.lat_deg)) *
                                                      std::cos(radians(b.lat_deg)) *
                                                      square(std::sin(dlon / 2.0));
  return 2.0 * kEarthRadiusM * std::asin(std::sqrt(std::fmin(1.0, h)));
}

void SiteSurvey::restart() {
  first_s_.reset();
  last_s_.reset();
  sum_lat_deg_ = sum_dlon_deg_ = sum_alt_m_ = 0.0;
  n_ = 0;
}

void SiteSurvey::on_fix(double now_s, const GpsFix& fix, int sats_used) {
  const bool good = usable_3d(fix) && sats_used >= settings_.min_sats;
  if (!good || (last_s_ && now_s - *last_s_ > kMaxGapS) || moved_away(fix)) restart();
  if (!good) return;
  if (!first_s_) {
    first_s_ = now_s;
    lon_ref_deg_ = fix.lon_deg;
  }
  last_s_ = now_s;
  sum_lat_deg_ += fix.lat_deg;
  sum_dlon_deg_ += dlon_deg(fix.lon_deg, lon_ref_deg_);
  sum_alt_m_ += *fix.alt_m;
  ++n_;
}

bool SiteSurvey::moved_away(const GpsFix& fix) const {
  if (n_ == 0) return false;
  const auto n = static_cast<double>(n_);
  const Site mean{sum_lat_deg_ / n, wrap_lon_deg(lon_ref_deg_ + sum_dlon_deg_ / n), 0.0};
  return ground_distance_m(mean, Site{fix.lat_deg, fix.lon_deg, 0.0}) > settings_.jump_m;
}

std::optional<Site> SiteSurvey::surveyed() const {
  if (n_ == 0 || *last_s_ - *first_s_ < settings_.hold_s) return std::nullopt;
  const auto n = static_cast<double>(n_);
  return Site{sum_lat_deg_ / n, wrap_lon_deg(lon_ref_deg_ + sum_dlon_deg_ / n), sum_alt_m_ / n};
}

std::string_view to_string(SiteDecision d) {
  switch (d) {
    case SiteDecision::Keep:
      return "keep";
    case SiteDecision::Adopt:
      return "adopt";
    case SiteDecision::Jump:
      return "jump";
  }
  return "keep";
}

SiteDecision decide_site(const std::optional<Site>& in_use, const Site& surveyed, bool tracking,
                         double jump_m) {
  if (!in_use) return SiteDecision::Adopt;
  const double moved_m = ground_distance_m(*in_use, surveyed);
  if (moved_m <= kSameSiteM) return SiteDecision::Keep;
  if (moved_m > jump_m && tracking) return SiteDecision::Jump;
  return SiteDecision::Adopt;
}

}  // namespace azt::gnss
