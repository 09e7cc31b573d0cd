#include "azt/eme/moon_windows.hpp"

#include <algorithm>
#include <cmath>

#include "azt/astro/sky.hpp"
#include "azt/eme/moon_conditions.hpp"

namespace azt::eme {
namespace {

constexpr double kSecondsPerDay = 86400.0;
constexpr double kEdgeToleranceS = 1.0;
constexpr double kBestMinuteS = 60.0;

/// Both stations' view of the Moon (and the Sun from the own station) at one instant.
struct Look {
  bool both_see = false;
  astro::Place moon;
  astro::Place dx_moon;
  astro::Place sun;
};

class MoonWatch {
 public:
  MoonWatch(const astro::Ephemeris& eph, const astro::Observer& own, const astro::Observer& dx,
            const MoonWindowSettings& s, const astro::LeapSecondTable& leaps)
      : eph_(eph), own_(own), dx_(dx), s_(s), leaps_(leaps) {}

  Result<Look> at(double unix_s) const {
    const auto time =
        astro::make_time_scales(astro::UtcInstant::from_unix_seconds(unix_s), s_.dut1_s, leaps_);
    if (!time) return time.error();
    const auto epoch = astro::make_epoch(eph_, *time);
    if (!epoch) return epoch.error();
    const auto moon = astro::observe_moon(eph_, *epoch, astro::make_station(*epoch, own_));
    const auto dx_moon = astro::observe_moon(eph_, *epoch, astro::make_station(*epoch, dx_));
    if (!moon) return moon.error();
    if (!dx_moon) return dx_moon.error();
    Look l{false, *moon, *dx_moon, {}};
    l.both_see = above(*moon, s_.min_el_deg, s_.mask) && below(*moon, s_.max_el_deg) &&
                 above(*dx_moon, s_.dx_min_el_deg, s_.dx_mask);
    if (l.both_see) l.sun = astro::observe_sun(*epoch, astro::make_station(*epoch, own_));
    return l;
  }

  [[nodiscard]] MoonConditions conditions(const Look& l) const {
    MoonInputs in;
    in.lat_deg = own_.lat_deg;
    in.moon = l.moon;
    in.sun = l.sun;
    in.dx_lat_deg = dx_.lat_deg;
    in.dx_moon = l.dx_moon;
    in.freq_mhz = s_.freq_mhz;
    return moon_conditions(in);
  }

 private:
  static bool above(const astro::Place& p, double min_el, const orbit::HorizonMask& mask) {
    return p.el_geometric_deg >= std::max(min_el, mask.min_el_at(p.az_deg));
  }
  static bool below(const astro::Place& p, const std::optional<double>& max_el) {
    return !max_el || p.el_geometric_deg <= *max_el;
  }

  const astro::Ephemeris& eph_;
  astro::Observer own_;
  astro::Observer dx_;
  const MoonWindowSettings& s_;
  const astro::LeapSecondTable& leaps_;
};

/// The instant between `seen` and `not_seen` (in either order) where visibility changes.
Result<double> edge(const MoonWatch& watch, double seen, double not_seen) {
  while (std::fabs(seen - not_seen) > kEdgeToleranceS) {
    const double mid = 0.5 * (seen + not_seen);
    const auto l = watch.at(mid);
    if (!l) return l.error();
    (l->both_see ? seen : not_seen) = mid;
  }
  return seen;
}

/// The best minute of a window: the coarse samples' best, then minute by minute around it.
Result<bool> fill_best(const MoonWatch& watch, MoonWindow& w, double step_s) {
  double best_t = w.start_unix_s;
  double best_dgrd = -1e9;
  auto consider = [&](double t) -> Result<bool> {
    const auto l = watch.at(t);
    if (!l) return l.error();
    if (!l->both_see) return true;
    const MoonConditions c = watch.conditions(*l);
    if (c.dgrd_db <= best_dgrd) return true;
    best_dgrd = c.dgrd_db;
    best_t = t;
    w.best_unix_s = t;
    w.dgrd_db = c.dgrd_db;
    w.tsky_k = c.tsky_k;
    w.dpol_deg = c.dx_dpol_deg.value_or(0.0);
    w.sun_sep_deg = c.sun_sep_deg;
    w.el_deg = l->moon.el_geometric_deg;
    w.dx_el_deg = l->dx_moon.el_geometric_deg;
    return true;
  };
  const double first = std::ceil(w.start_unix_s / kBestMinuteS) * kBestMinuteS;
  const auto coarse_count = static_cast<long>(std::floor((w.end_unix_s - first) / step_s));
  for (long i = 0; i <= coarse_count; ++i) {
    if (auto r = consider(first + static_cast<double>(i) * step_s); !r) return r;
  }
  const double coarse = best_t;
  const auto minutes = static_cast<long>(step_s / kBestMinuteS);
  for (long i = -minutes; i <= minutes; ++i) {
    const double t = coarse + static_cast<double>(i) * kBestMinuteS;
    if (t < w.start_unix_s || t > w.end_unix_s) continue;
    if (auto r = consider(t); !r) return r;
  }
  if (best_dgrd < -1e8) {  // shorter than a minute: its middle
    if (auto r = consider(0.5 * (w.start_unix_s + w.end_unix_s)); !r) return r;
  }
  return true;
}

/// The search's step: a fixed-elevation array's band is never crossed between two samples.
double sample_step_s(const MoonWindowSettings& s) {
  constexpr double kSecondsPerBandDeg = 120.0;  // half the 240 s/° of the Moon's fastest climb
  if (!s.max_el_deg) return s.step_s;
  const double band_deg = std::max(*s.max_el_deg - s.min_el_deg, 0.1);
  return std::min(s.step_s, kSecondsPerBandDeg * band_deg);
}

}  // namespace

MoonWindowSettings in_fixed_beam(MoonWindowSettings s, double fixed_el_deg, double beam_width_deg) {
  s.min_el_deg = std::max(s.min_el_deg, fixed_el_deg - beam_width_deg / 2.0);
  s.max_el_deg = fixed_el_deg + beam_width_deg / 2.0;
  return s;
}

Result<std::vector<MoonWindow>> moon_windows(const astro::Ephemeris& ephemeris,
                                             const astro::Observer& own, const astro::Observer& dx,
                                             const MoonWindowSettings& settings,
                                             const astro::LeapSecondTable& leap_seconds) {
  const MoonWatch watch(ephemeris, own, dx, settings, leap_seconds);
  const double step_s = sample_step_s(settings);
  const double end = settings.from_unix_s + settings.days * kSecondsPerDay;
  std::vector<MoonWindow> windows;
  std::optional<double> open;  // the start of the window under way
  double prev_t = settings.from_unix_s;
  bool prev_seen = false;
  for (double t = settings.from_unix_s;; t = std::min(t + step_s, end)) {
    const auto l = watch.at(t);
    if (!l) return l.error();
    if (l->both_see && !prev_seen) {
      if (t == settings.from_unix_s) {
        open = t;
      } else {
        const auto e = edge(watch, t, prev_t);
        if (!e) return e.error();
        open = *e;
      }
    } else if (!l->both_see && prev_seen) {
      const auto e = edge(watch, prev_t, t);
      if (!e) return e.error();
      windows.push_back(MoonWindow{*open, *e});
      open.reset();
    }
    prev_t = t;
    prev_seen = l->both_see;
    if (t >= end) break;
  }
  if (open) windows.push_back(MoonWindow{*open, end});
  for (auto& w : windows) {
    if (auto r = fill_best(watch, w, step_s); !r) return r.error();
  }
  return windows;
}

}  // namespace azt::eme
