#include "azt/track/pass_plan.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace azt::track {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

/// Rate limiting forwards and backwards in time, averaged: a path no faster than `rate` that is
/// as early as it is late around a swing the input makes too fast.
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

struct Option {
  PassPlan plan;
  double preposition_deg = 0.0;
};

/// Worst error first (to a tenth of a degree: closer than that is a tie), then pre-positioning.
bool better(const Option& a, const Option& b) {
  const double ea = std::round(a.plan.max_error_deg * 10.0);
  const double eb = std::round(b.plan.max_error_deg * 10.0);
  if (ea != eb) return ea < eb;
  if (std::fabs(a.preposition_deg - b.preposition_deg) > 1.0) {
    return a.preposition_deg < b.preposition_deg;
  }
  return !a.plan.flip && b.plan.flip;
}

/// How the pass is flown: normal or flipped before the highest point, and after it. Changing at
/// the top is continuous for a pass through the zenith ("over the top").
struct Mode {
  bool flip_before = false;
  bool flip_after = false;
};

/// The pass flown in `mode`: the mount azimuth unwrapped and shifted by whole turns to the travel.
/// When no shift holds the whole sweep, the mount waits at the stop for the part it cannot reach
/// (it never unwinds mid-pass): of the shifts, the one with the least worst error wins, then the
/// one nearest where the mount stands.
Option fly(const std::vector<SkyPoint>& sky, const MountGeometry& m, Mode mode, std::size_t top,
           double current_az) {
  const std::size_t n = sky.size();
  std::vector<double> t(n);
  std::vector<double> az(n);
  std::vector<double> el(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool flip = i <= top ? mode.flip_before : mode.flip_after;
    const double el_top = flip ? m.el.max_deg : std::min(m.el.max_deg, 90.0);
    t[i] = sky[i].t_s;
    const double a = flip ? sky[i].az_deg + 180.0 : sky[i].az_deg;
    // Unwrapped: each step the short way round, so the mount angle is continuous.
    az[i] = i == 0 ? control::wrap_360(a) : az[i - 1] + std::remainder(a - az[i - 1], 360.0);
    el[i] = std::clamp(flip ? 180.0 - sky[i].el_deg : sky[i].el_deg, m.el.min_deg, el_top);
  }
  const auto [lo, hi] = std::minmax_element(az.begin(), az.end());
  const double k_first = std::floor((m.az.min_deg - *hi) / 360.0);
  const double k_last = std::ceil((m.az.max_deg - *lo) / 360.0);
  std::optional<Option> best;
  const auto turns = static_cast<int>(k_last - k_first);
  for (int j = 0; j <= turns; ++j) {
    const double k = k_first + j;
    std::vector<double> shifted(n);
    for (std::size_t i = 0; i < n; ++i) {
      shifted[i] = std::clamp(az[i] + 360.0 * k, m.az.min_deg, m.az.max_deg);
    }
    Option o;
    o.plan.flip = mode.flip_before || mode.flip_after;
    const std::vector<double> az_cmd = centred_rate_limit(t, shifted, m.max_az_rate_deg_s);
    const std::vector<double> el_cmd = centred_rate_limit(t, el, m.max_el_rate_deg_s);
    o.plan.track.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      o.plan.track[i] = MountPoint{t[i], az_cmd[i], el_cmd[i]};
      if (i > 0) o.plan.az_travel_deg += std::fabs(az_cmd[i] - az_cmd[i - 1]);
      const SkyPoint beam = mount_to_sky(o.plan.track[i]);
      o.plan.max_error_deg =
          std::max(o.plan.max_error_deg, separation_deg(beam.az_deg, beam.el_deg, sky[i].az_deg,
                                                        std::max(sky[i].el_deg, m.el.min_deg)));
    }
    o.preposition_deg = std::fabs(az_cmd[0] - current_az);
    if (!best || better(o, *best)) best = std::move(o);
  }
  return std::move(*best);
}

}  // namespace

double separation_deg(double az1_deg, double el1_deg, double az2_deg, double el2_deg) {
  const double a1 = az1_deg * kRad;
  const double e1 = el1_deg * kRad;
  const double a2 = az2_deg * kRad;
  const double e2 = el2_deg * kRad;
  // Vincenty's form: well conditioned at every angle.
  const double da = a2 - a1;
  const double x = std::sin(e1) * std::sin(e2) + std::cos(e1) * std::cos(e2) * std::cos(da);
  const double y1 = std::cos(e2) * std::sin(da);
  const double y2 = std::cos(e1) * std::sin(e2) - std::sin(e1) * std::cos(e2) * std::cos(da);
  return std::atan2(std::hypot(y1, y2), x) / kRad;
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
  std::size_t top = 0;
  for (std::size_t i = 1; i < sky.size(); ++i) {
    if (sky[i].el_deg > sky[top].el_deg) top = i;
  }
  std::optional<Option> best;
  for (const Mode mode :
       {Mode{false, false}, Mode{true, true}, Mode{false, true}, Mode{true, false}}) {
    if ((mode.flip_before || mode.flip_after) && !mount.can_flip()) continue;
    Option o = fly(sky, mount, mode, top, current_az_mount_deg);
    if (!best || better(o, *best)) best = std::move(o);
  }
  return std::move(best->plan);
}

MountGeometry mount_geometry(const control::StationSetup& station) {
  MountGeometry m;
  m.az = station.az_range;
  m.el = station.el_range;
  m.max_az_rate_deg_s = station.az_control.max_rate_deg_s;
  m.max_el_rate_deg_s = station.el_control.max_rate_deg_s;
  return m;
}

}  // namespace azt::track
