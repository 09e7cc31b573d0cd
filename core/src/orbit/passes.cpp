#include "azt/orbit/passes.hpp"
#include "azt/util/angles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace azt::orbit {
namespace {

struct Sample {
  double t = 0.0;
  LookAngles look;
};

/// The search over one window: samples, brackets and refinements.
class Search {
 public:
  Search(const LookFunction& look, const PassSearch& s) : look_(look), s_(s) {}

  Result<std::vector<Pass>> run() {
    const double lowest = std::min(0.0, s_.mask.lowest());
    std::vector<Sample> recent;  // the last three samples
    double t = s_.from_s;
    while (true) {
      auto sample = at(t);
      if (!sample) return sample.error();
      recent.push_back(*sample);
      if (recent.size() > 3) recent.erase(recent.begin());
      if (t == s_.from_s && recent.size() == 1 && above(recent[0]) && !rising_at_start(recent[0])) {
        // The window opens in a pass that is already past its highest point.
        if (auto r = add_pass(recent[0].t, true, false); !r) return r.error();
        if (!restart(recent, t)) break;
        continue;
      }
      if (recent.size() == 3 && recent[1].look.el_deg >= recent[0].look.el_deg &&
          recent[1].look.el_deg > recent[2].look.el_deg) {
        auto peak = highest(recent[0].t, recent[2].t);
        if (!peak) return peak.error();
        if (above(*peak)) {
          if (auto r = add_pass(peak->t, false, false); !r) return r.error();
          if (!restart(recent, t)) break;
          continue;
        }
      }
      if (t >= s_.to_s) {
        // Still rising at the end of the window: a pass cut by it.
        if (above(recent.back())) {
          if (auto r = add_pass(t, false, true); !r) return r.error();
        }
        break;
      }
      t = std::min(s_.to_s, t + step(recent.back(), lowest));
    }
    return passes_;
  }

 private:
  Result<Sample> at(double t) const {
    auto l = look_(t);
    if (!l) return l.error();
    return Sample{t, *l};
  }

  [[nodiscard]] bool above(const Sample& s) const {
    return s.look.el_deg > s_.mask.min_el_at(s.look.az_deg);
  }

  bool rising_at_start(const Sample& s) {
    auto next = at(std::min(s_.to_s, s.t + s_.time_tolerance_s * 10.0));
    return next && next->look.el_deg > s.look.el_deg;
  }

  /// Far below the horizon the satellite cannot rise before (gap in radians) · d / v.
  [[nodiscard]] double step(const Sample& s, double lowest) const {
    const double gap_deg = lowest - s.look.el_deg;
    if (gap_deg <= 1.0 || s_.horizon_km <= 0.0 || s_.max_speed_km_s <= 0.0) return s_.base_step_s;
    return std::max(s_.base_step_s, 0.8 * gap_deg * kRadPerDeg * s_.horizon_km / s_.max_speed_km_s);
  }

  /// After a pass, sampling starts again just after its end.
  bool restart(std::vector<Sample>& recent, double& t) const {
    recent.clear();
    if (passes_.back().ends_after_window) return false;
    t = passes_.back().los_s + s_.base_step_s;
    return t <= s_.to_s;
  }

  /// Golden-section search for the highest elevation in [a, b].
  Result<Sample> highest(double a, double b) const {
    const double r = (std::sqrt(5.0) - 1.0) / 2.0;
    double x1 = b - r * (b - a);
    double x2 = a + r * (b - a);
    auto f1 = at(x1);
    auto f2 = at(x2);
    if (!f1) return f1.error();
    if (!f2) return f2.error();
    while (b - a > s_.time_tolerance_s) {
      if (f1->look.el_deg >= f2->look.el_deg) {
        b = x2;
        x2 = x1;
        f2 = f1;
        x1 = b - r * (b - a);
        f1 = at(x1);
        if (!f1) return f1.error();
      } else {
        a = x1;
        x1 = x2;
        f1 = f2;
        x2 = a + r * (b - a);
        f2 = at(x2);
        if (!f2) return f2.error();
      }
    }
    return at((a + b) / 2.0);
  }

  /// The crossing of the mask between `inside` (above) and `outside` (below), by bisection.
  Result<Sample> crossing(double inside, double outside) const {
    while (std::fabs(outside - inside) > s_.time_tolerance_s) {
      const double mid = (inside + outside) / 2.0;
      auto m = at(mid);
      if (!m) return m.error();
      (above(*m) ? inside : outside) = mid;
    }
    return at(inside);
  }

  /// Walks from `from` in `direction` (−1, +1) until below the mask, then bisects; the window's
  /// edge if it is reached first.
  Result<std::pair<Sample, bool>> edge(double from, int direction) const {
    const double limit = direction < 0 ? s_.from_s : s_.to_s;
    double inside = from;
    while (true) {
      const double next = direction < 0 ? std::max(limit, inside - s_.base_step_s)
                                        : std::min(limit, inside + s_.base_step_s);
      auto s = at(next);
      if (!s) return s.error();
      if (!above(*s)) {
        auto c = crossing(inside, next);
        if (!c) return c.error();
        return std::pair{*c, false};
      }
      if (next == limit) return std::pair{*s, true};
      inside = next;
    }
  }

  Result<bool> add_pass(double tca_s, bool clipped_start, bool clipped_end) {
    auto tca = at(tca_s);
    if (!tca) return tca.error();
    auto rise =
        clipped_start ? Result<std::pair<Sample, bool>>(std::pair{*tca, true}) : edge(tca_s, -1);
    if (!rise) return rise.error();
    auto set =
        clipped_end ? Result<std::pair<Sample, bool>>(std::pair{*tca, true}) : edge(tca_s, +1);
    if (!set) return set.error();
    Pass p;
    p.aos_s = rise->first.t;
    p.tca_s = tca_s;
    p.los_s = set->first.t;
    p.max_el_deg = tca->look.el_deg;
    p.aos_az_deg = rise->first.look.az_deg;
    p.tca_az_deg = tca->look.az_deg;
    p.los_az_deg = set->first.look.az_deg;
    p.starts_before_window = rise->second;
    p.ends_after_window = set->second;
    passes_.push_back(p);
    return true;
  }

  const LookFunction& look_;
  const PassSearch& s_;
  std::vector<Pass> passes_;
};

}  // namespace

Result<HorizonMask> HorizonMask::make(std::vector<std::pair<double, double>> sectors) {
  if (sectors.empty() || sectors.size() > 72) return fail("horizon mask: 1 to 72 sectors");
  for (std::size_t i = 0; i < sectors.size(); ++i) {
    const auto [az, el] = sectors[i];
    if (!std::isfinite(az) || az < 0.0 || az >= 360.0) {
      return fail("horizon mask: sector azimuths must be 0 to < 360");
    }
    if (i > 0 && az <= sectors[i - 1].first) {
      return fail("horizon mask: sector azimuths must increase");
    }
    if (!std::isfinite(el) || el < -10.0 || el > 90.0) {
      return fail("horizon mask: elevations must be −10 to 90°");
    }
  }
  HorizonMask m;
  m.sectors_ = std::move(sectors);
  return m;
}

HorizonMask HorizonMask::flat(double min_el_deg) {
  HorizonMask m;
  m.sectors_ = {{0.0, min_el_deg}};
  return m;
}

double HorizonMask::min_el_at(double az_deg) const {
  // The sector whose start is the last one at or before az; before the first: the last (wrap).
  const double az = az_deg - 360.0 * std::floor(az_deg / 360.0);
  double el = sectors_.back().second;
  for (const auto& [from, min_el] : sectors_) {
    if (from > az) break;
    el = min_el;
  }
  return el;
}

double HorizonMask::lowest() const {
  double low = sectors_.front().second;
  for (const auto& s : sectors_) low = std::min(low, s.second);
  return low;
}

Result<std::vector<Pass>> find_passes(const LookFunction& look, const PassSearch& search) {
  if (!(search.to_s > search.from_s)) return fail("pass search: the window is empty");
  if (!(search.base_step_s > 0.0) || !(search.time_tolerance_s > 0.0)) {
    return fail("pass search: steps must be positive");
  }
  return Search(look, search).run();
}

PassSearch orbit_pass_search(double rev_day, double eccentricity, double from_s, double to_s,
                             const HorizonMask& mask) {
  constexpr double kMuKm3S2 = 398600.8;  // WGS-72, as SGP4
  constexpr double kEquatorKm = 6378.135;
  constexpr double kPoleKm = 6356.75;
  PassSearch s;
  s.from_s = from_s;
  s.to_s = to_s;
  s.mask = mask;
  const double period_s = 86400.0 / rev_day;
  s.base_step_s = std::clamp(period_s / 200.0, 5.0, 600.0);
  const double n_rad_s = rev_day * 2.0 * std::numbers::pi / 86400.0;
  const double a_km = std::cbrt(kMuKm3S2 / (n_rad_s * n_rad_s));
  const double perigee_km = a_km * (1.0 - eccentricity);
  // The least horizon distance: the smallest Earth radius with the height above the largest.
  const double h_km = std::max(50.0, perigee_km - kEquatorKm);
  s.horizon_km = std::sqrt(2.0 * kPoleKm * h_km + h_km * h_km);
  // Perigee speed, plus the site's own motion (0.47 km/s at the equator) and a margin.
  s.max_speed_km_s = std::sqrt(kMuKm3S2 * (2.0 / perigee_km - 1.0 / a_km)) + 1.0;
  return s;
}

}  // namespace azt::orbit
