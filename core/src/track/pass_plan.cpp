#include "azt/track/pass_plan.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "azt/track/rate_limited_path.hpp"
#include "azt/util/angles.hpp"

namespace azt::track {
namespace {
/// Halvings of the error bracket: 180° / 2^18 is 2.5 arcseconds.
constexpr int kBisections = 18;
/// Equally short lost stretches compared for their worst error: a handful spread over the pass.
constexpr std::size_t kStretchesCompared = 8;

/// Rate limiting forwards and backwards in time, averaged: a path no faster than `rate` that is
/// as early as it is late around a move the input makes too fast (the elevation's flips).
std::vector<double> centred_rate_limit(const std::vector<double>& t, const std::vector<double>& x,
                                       double rate) {
  const std::size_t n = x.size();
  std::vector<double> fwd(x);
  std::vector<double> bwd(x);
  for (std::size_t i = 1; i < n; ++i) {
    const double step = rate * (t[i] - t[i - 1]);
    fwd[i] = std::clamp(x[i], fwd[i - 1] - step, fwd[i - 1] + step);
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    const double step = rate * (t[i + 1] - t[i]);
    bwd[i] = std::clamp(x[i], bwd[i + 1] - step, bwd[i + 1] + step);
  }
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = (fwd[i] + bwd[i]) / 2.0;
  return out;
}

/// How far the mount azimuth may stray from the satellite's with the beam still within `err` of
/// it, the elevation set to the satellite's projection on the plane the elevation axis sweeps:
/// cos(el)·|sin Δaz| ≤ sin(err). Once err reaches the zenith distance, any azimuth will do.
double half_width_deg(double err_deg, double el_deg) {
  const double s = std::sin(std::min(err_deg, 90.0) * kRadPerDeg) / std::cos(el_deg * kRadPerDeg);
  return s >= 1.0 ? 180.0 : std::asin(s) / kRadPerDeg;
}

/// The error an azimuth `delta_deg` off costs at `el_deg` with the best elevation.
double off_by_deg(double delta_deg, double el_deg) {
  return std::asin(std::min(
             1.0, std::cos(el_deg * kRadPerDeg) * std::fabs(std::sin(delta_deg * kRadPerDeg)))) /
         kRadPerDeg;
}

/// The pass as the planner sees it, and the azimuths its mount may take.
struct Planner {
  const MountGeometry& m;
  std::vector<double> t;
  std::vector<double> az;  ///< the satellite's
  std::vector<double> el;  ///< the satellite's, not below the mount's lowest
  double period = 360.0;  ///< 180 on a flip mount: az + 180° at 180° − el is the same direction

  [[nodiscard]] Spans travel() const { return {{m.az.min_deg, m.az.max_deg}}; }

  /// The azimuths (in every turn or half turn of the travel) within err at sample i.
  [[nodiscard]] Spans allowed_at(std::size_t i, double err) const {
    const double w = half_width_deg(err, el[i]);
    if (w >= period / 2.0) return travel();
    Spans out;
    const double first = az[i] + period * std::floor((m.az.min_deg - w - az[i]) / period);
    for (double c = first; c - w <= m.az.max_deg; c += period) {
      const double lo = std::max(c - w, m.az.min_deg);
      const double hi = std::min(c + w, m.az.max_deg);
      if (lo <= hi) out.push_back({lo, hi});
    }
    return out;
  }

  [[nodiscard]] std::vector<Spans> allowed(const std::function<double(std::size_t)>& err) const {
    std::vector<Spans> out(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) out[i] = allowed_at(i, err(i));
    return out;
  }

  [[nodiscard]] bool feasible(const std::function<double(std::size_t)>& err) const {
    return !reachable_forward(t, allowed(err), m.max_az_rate_deg_s, travel()).back().empty();
  }
};

/// The least error bound in [lo, hi] that `works` (hi must).
double least(double lo, double hi, const std::function<bool(double)>& works) {
  for (int k = 0; k < kBisections; ++k) {
    const double mid = (lo + hi) / 2.0;
    (works(mid) ? hi : lo) = mid;
  }
  return hi;
}

/// The samples [a, b) in which the beam may be off the satellite.
struct Stretch {
  std::size_t a = 0;
  std::size_t b = 0;
};

/// How long a stretch lets the beam be off: from the last kept sample before it to the first
/// after it.
double stretch_s(const Planner& p, Stretch s) {
  const double from = s.a == 0 ? p.t.front() : p.t[s.a - 1];
  const double to = s.b == p.t.size() ? p.t.back() : p.t[s.b];
  return to - from;
}

/// Where the mount can be while keeping the beam within the loss bound: from the start, and
/// towards the end.
struct KeptReach {
  std::vector<Spans> fwd;
  std::vector<Spans> bwd;
};

/// The shortest stretches off the satellite that let the beam be within the loss bound elsewhere
/// (two pointers: the shortest stretch from a later start never ends earlier). Inside a stretch
/// the mount is free within its travel, so a stretch works when the reachable sets before and
/// after it are within the rate of each other across it.
std::vector<Stretch> shortest_stretches(const Planner& p, const KeptReach& kept) {
  const std::size_t n = p.t.size();
  const double rate = p.m.max_az_rate_deg_s;
  const std::vector<Spans>& fwd = kept.fwd;
  const std::vector<Spans>& bwd = kept.bwd;
  const auto works = [&](Stretch s) {
    if (s.a > 0 && fwd[s.a - 1].empty()) return false;
    if (s.b < n && bwd[s.b].empty()) return false;
    if (s.a == 0 || s.b == n) return true;
    return gap(fwd[s.a - 1], bwd[s.b]) <= rate * (p.t[s.b] - p.t[s.a - 1]) + 1e-9;
  };
  std::vector<Stretch> found;
  std::size_t b = 1;
  for (std::size_t a = 0; a < n; ++a) {
    b = std::max(b, a + 1);
    while (b < n && !works({a, b})) ++b;
    if (works({a, b})) found.push_back({a, b});
  }
  double shortest = 1e300;
  for (const Stretch& s : found) shortest = std::min(shortest, stretch_s(p, s));
  std::vector<Stretch> ties;
  for (const Stretch& s : found) {
    if (stretch_s(p, s) <= shortest + 1.0) ties.push_back(s);
  }
  return ties;
}

/// Whether the beam can be kept within `err` through the stretch and within the loss bound
/// elsewhere: only the stretch is walked, between the reachable sets kept before and after it.
bool stretch_works(const Planner& p, const KeptReach& kept, Stretch s, double err) {
  const double rate = p.m.max_az_rate_deg_s;
  Spans reach = s.a == 0 ? p.travel() : kept.fwd[s.a - 1];
  for (std::size_t i = s.a; i < s.b; ++i) {
    if (i > 0) reach = widened(reach, rate * (p.t[i] - p.t[i - 1]));
    reach = intersection(reach, p.allowed_at(i, err));
    if (reach.empty()) return false;
  }
  if (s.b == p.t.size()) return true;
  const Spans next = widened(reach, rate * (p.t[s.b] - p.t[s.b - 1]));
  return !intersection(next, kept.bwd[s.b]).empty();
}

/// Of the equally short stretches (a handful, spread), the one whose worst error is least, and
/// the per-sample error bound that flies it.
std::function<double(std::size_t)> least_loss(const Planner& p) {
  const double keep = p.m.loss_error_deg;
  const std::vector<Spans> kept_sets = p.allowed([&](std::size_t) { return keep; });
  const KeptReach kept{reachable_forward(p.t, kept_sets, p.m.max_az_rate_deg_s, p.travel()),
                       reachable_backward(p.t, kept_sets, p.m.max_az_rate_deg_s)};
  const std::vector<Stretch> ties = shortest_stretches(p, kept);
  double best_err = 1e300;
  Stretch best{};
  const std::size_t step = std::max<std::size_t>(1, ties.size() / kStretchesCompared);
  for (std::size_t k = 0; k < ties.size(); k += step) {
    const Stretch s = ties[k];
    const double e =
        least(keep, 180.0, [&](double bound) { return stretch_works(p, kept, s, bound); });
    if (e < best_err) {
      best_err = e;
      best = s;
    }
  }
  return
      [best, best_err, keep](std::size_t i) { return i >= best.a && i < best.b ? best_err : keep; };
}

/// The azimuth path for the error bounds: begun in the turn nearest where the mount stands, each
/// moment as near the satellite's azimuth as the path allows (not flipped, other things equal).
std::vector<double> azimuth_path(const Planner& p, const std::function<double(std::size_t)>& err,
                                 double current_az) {
  const std::vector<Spans> allowed = p.allowed(err);
  Spans starts = allowed.front();
  std::sort(starts.begin(), starts.end(), [&](Span x, Span y) {
    return gap({x}, {{current_az, current_az}}) < gap({y}, {{current_az, current_az}});
  });
  const auto prefer = [&](std::size_t i, Span s, std::optional<double>) {
    std::pair<double, double> best{s.lo, 1e300};
    for (const double shift : {0.0, 180.0}) {
      if (shift > 0.0 && p.period > 180.0) continue;
      const double c0 = p.az[i] + shift;
      const double mid = (s.lo + s.hi) / 2.0;
      const double c = c0 + 360.0 * std::round((mid - c0) / 360.0);
      for (const double centre : {c - 360.0, c, c + 360.0}) {
        const double at = std::clamp(centre, s.lo, s.hi);
        const double cost = std::fabs(at - centre) + (shift > 0.0 ? 1e-3 : 0.0);
        if (cost < best.second) best = {at, cost};
      }
    }
    return best;
  };
  for (const Span& s : starts) {
    const std::vector<Spans> reach =
        reachable_forward(p.t, allowed, p.m.max_az_rate_deg_s, Spans{s});
    if (!reach.back().empty()) return path_through(p.t, reach, p.m.max_az_rate_deg_s, prefer);
  }
  return {};  // unreachable: the bounds were found feasible from some start
}

/// The elevation for a mount azimuth `delta_deg` off the satellite's: the satellite's projection
/// on the plane the elevation axis sweeps (past 90° on a flip mount), or, at a lost moment, the
/// satellite's own elevation (the dish is not raised and lowered across a swing).
double elevation_for(double el_deg, double delta_deg, const MountGeometry& m) {
  const bool behind = std::fabs(delta_deg) > 90.0;
  const bool lost = off_by_deg(delta_deg, el_deg) > m.loss_error_deg;
  double e = 0.0;
  if (!m.can_flip() && behind) {
    e = 90.0 - el_deg <= m.loss_error_deg ? 90.0 : el_deg;
  } else if (lost) {
    e = behind ? 180.0 - el_deg : el_deg;
  } else {
    e = std::atan2(std::sin(el_deg * kRadPerDeg),
                   std::cos(el_deg * kRadPerDeg) * std::cos(delta_deg * kRadPerDeg)) /
        kRadPerDeg;
  }
  return std::clamp(e, m.el.min_deg, m.can_flip() ? m.el.max_deg : std::min(m.el.max_deg, 90.0));
}

/// The lost stretch as the mount flies it: the axis takes `ramp_s` to reach full speed as the
/// swing starts, and as long to settle back on the satellite after it.
void widen_by_ramps(PassPlan& plan, double aos_s, double los_s, double ramp_s) {
  const double from = std::max(aos_s, plan.loss_from_s - ramp_s);
  const double to = std::min(los_s, plan.loss_to_s + ramp_s);
  plan.loss_s += (plan.loss_from_s - from) + (to - plan.loss_to_s);
  plan.loss_from_s = from;
  plan.loss_to_s = to;
}

/// The plan's track from the azimuth path, with its errors and losses measured exactly.
PassPlan assemble(const Planner& p, const std::vector<double>& az_cmd) {
  const std::size_t n = p.t.size();
  std::vector<double> el_want(n);
  for (std::size_t i = 0; i < n; ++i) {
    el_want[i] = elevation_for(p.el[i], std::remainder(az_cmd[i] - p.az[i], 360.0), p.m);
  }
  const std::vector<double> el_cmd = centred_rate_limit(p.t, el_want, p.m.max_el_rate_deg_s);
  PassPlan plan;
  plan.loss_error_deg = p.m.loss_error_deg;
  plan.track.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    plan.track[i] = MountPoint{p.t[i], az_cmd[i], el_cmd[i]};
    plan.flip = plan.flip || el_cmd[i] > 90.0;
    const SkyPoint beam = mount_to_sky(plan.track[i]);
    const double err = separation_deg(beam.az_deg, beam.el_deg, p.az[i], p.el[i]);
    plan.max_error_deg = std::max(plan.max_error_deg, err);
    if (i == 0) continue;
    plan.az_travel_deg += std::fabs(az_cmd[i] - az_cmd[i - 1]);
    if (err > p.m.loss_error_deg) {
      if (plan.loss_s == 0.0) plan.loss_from_s = p.t[i - 1];
      plan.loss_s += p.t[i] - p.t[i - 1];
      plan.loss_to_s = p.t[i];
    }
  }
  if (plan.loss_s > 0.0) widen_by_ramps(plan, p.t.front(), p.t.back(), p.m.ramp_s);
  return plan;
}

}  // namespace

double separation_deg(double az1_deg, double el1_deg, double az2_deg, double el2_deg) {
  const double a1 = az1_deg * kRadPerDeg;
  const double e1 = el1_deg * kRadPerDeg;
  const double a2 = az2_deg * kRadPerDeg;
  const double e2 = el2_deg * kRadPerDeg;
  // Vincenty's form: well conditioned at every angle.
  const double da = a2 - a1;
  const double x = std::sin(e1) * std::sin(e2) + std::cos(e1) * std::cos(e2) * std::cos(da);
  const double y1 = std::cos(e2) * std::sin(da);
  const double y2 = std::cos(e1) * std::sin(e2) - std::sin(e1) * std::cos(e2) * std::cos(da);
  return std::atan2(std::hypot(y1, y2), x) / kRadPerDeg;
}

SkyPoint mount_to_sky(const MountPoint& m) {
  if (m.el_deg > 90.0) return {m.t_s, control::wrap_360(m.az_deg + 180.0), 180.0 - m.el_deg};
  return {m.t_s, control::wrap_360(m.az_deg), m.el_deg};
}

MountPoint PassPlan::at(double t_s) const {
  if (track.empty()) return {};
  if (t_s <= track.front().t_s) return track.front();
  if (t_s >= track.back().t_s) return track.back();
  const auto it = std::upper_bound(track.begin(), track.end(), t_s,
                                   [](double t, const MountPoint& p) { return t < p.t_s; });
  const MountPoint& b = *it;
  const MountPoint& a = *(it - 1);
  const double f = (t_s - a.t_s) / (b.t_s - a.t_s);
  return {t_s, a.az_deg + f * (b.az_deg - a.az_deg), a.el_deg + f * (b.el_deg - a.el_deg)};
}

Result<PassPlan> plan_pass(const std::vector<SkyPoint>& sky, const MountGeometry& mount,
                           double current_az_mount_deg) {
  if (sky.size() < 2) return fail("pass plan: at least two samples");
  for (std::size_t i = 0; i < sky.size(); ++i) {
    if (!std::isfinite(sky[i].t_s) || !std::isfinite(sky[i].az_deg) ||
        !std::isfinite(sky[i].el_deg) || (i > 0 && sky[i].t_s <= sky[i - 1].t_s)) {
      return fail("pass plan: samples must be finite and in increasing time");
    }
  }
  Planner p{mount, {}, {}, {}, mount.can_flip() ? 180.0 : 360.0};
  for (const SkyPoint& s : sky) {
    p.t.push_back(s.t_s);
    p.az.push_back(control::wrap_360(s.az_deg));
    p.el.push_back(std::clamp(s.el_deg, mount.el.min_deg, 90.0));
  }
  const double worst = least(
      0.0, 180.0, [&](double bound) { return p.feasible([bound](std::size_t) { return bound; }); });
  std::function<double(std::size_t)> err = [worst](std::size_t) { return worst; };
  if (worst > mount.loss_error_deg) err = least_loss(p);
  return assemble(p, azimuth_path(p, err, current_az_mount_deg));
}

MountGeometry mount_geometry(const control::StationSetup& station) {
  MountGeometry m;
  m.az = station.az_range;
  m.el = station.el_range;
  m.max_az_rate_deg_s = station.az_control.max_rate_deg_s;
  m.max_el_rate_deg_s = station.el_control.max_rate_deg_s;
  m.ramp_s = station.az_control.ramp_s + station.az_control.time_constant_s;
  return m;
}

}  // namespace azt::track
