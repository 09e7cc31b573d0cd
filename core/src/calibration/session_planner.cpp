#include "azt/calibration/session_planner.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace azt::calibration {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
/// Where a source is checked during its scan: at its start, every quarter, and at its end.
constexpr int kSamples = 4;

}  // namespace

SessionPlanner::SessionPlanner(std::vector<PlanSource> sources, SourcePosition position,
                               SiteLimits limits, PlanSettings settings)
    : sources_(std::move(sources)),
      position_(std::move(position)),
      limits_(std::move(limits)),
      settings_(settings),
      coverage_(limits_.min_el_deg, limits_.max_el_deg),
      last_fitted_s_(sources_.size()),
      last_failed_s_(sources_.size()) {}

bool SessionPlanner::within_limits(const control::AzEl& at) const {
  const double floor_deg = limits_.horizon_el_deg
                               ? std::max(limits_.min_el_deg, limits_.horizon_el_deg(at.az_deg))
                               : limits_.min_el_deg;
  return at.el_deg >= floor_deg && at.el_deg <= limits_.max_el_deg;
}

bool SessionPlanner::clear_of_stops(const control::AzEl& at) const {
  // A scan reaches ± half_span beamwidths, in azimuth 1/cos E as much; a beamwidth more spare.
  const control::AzimuthRange& range = limits_.az_range;
  const double cos_el = std::max(std::cos(at.el_deg * kDegToRad), 0.05);
  const double margin = settings_.beamwidth_deg * (2.0 * settings_.half_span_beams / cos_el + 1.0);
  if (range.max_deg - range.min_deg >= 360.0 + 2.0 * margin) return true;
  const double az =
      range.min_deg + std::fmod(std::fmod(at.az_deg - range.min_deg, 360.0) + 360.0, 360.0);
  return az - range.min_deg >= margin && range.max_deg - az >= margin;
}

bool SessionPlanner::confused(std::size_t index, const control::AzEl& at, double t_s) const {
  const double near_deg = settings_.confusion_beams * settings_.beamwidth_deg;
  for (std::size_t j = 0; j < sources_.size(); ++j) {
    if (j == index || sources_[j].snr_db < settings_.confusion_snr_db) continue;
    const auto other = position_(j, t_s);
    if (other && separation_deg(*other, at) < near_deg) return true;
  }
  return false;
}

bool SessionPlanner::usable(std::size_t index, double t_s) const {
  if (index >= sources_.size() || sources_[index].snr_db < settings_.min_snr_db) return false;
  const auto& failed = last_failed_s_[index];
  if (failed && t_s - *failed < settings_.retry_s) return false;
  for (int k = 0; k <= kSamples; ++k) {
    const auto at = position_(index, t_s + settings_.scan_s * k / kSamples);
    if (!at || !within_limits(*at) || !clear_of_stops(*at)) return false;
  }
  const auto now = position_(index, t_s);
  return !confused(index, *now, t_s);
}

bool SessionPlanner::by_period(std::size_t index) const {
  return sources_[index].periodic && settings_.every_s > 0.0;
}

bool SessionPlanner::due(std::size_t index, double t_s) const {
  const auto& last = last_fitted_s_[index];
  return !last || t_s - *last >= settings_.every_s;
}

std::optional<PlannedScan> SessionPlanner::next(double now_s) const {
  if (done()) return std::nullopt;
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    if (by_period(i) && due(i, now_s) && usable(i, now_s)) {
      return PlannedScan{i, now_s, *position_(i, now_s)};
    }
  }
  const double error = coverage_.sky_error();
  std::optional<PlannedScan> best;
  double best_gain = settings_.min_gain;
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    if (by_period(i) || !usable(i, now_s)) continue;
    // Coverage where the scan will be, halfway through.
    const auto middle = position_(i, now_s + 0.5 * settings_.scan_s);
    const double gain = middle ? (error - coverage_.sky_error_with(*middle)) / error : 0.0;
    if (gain >= best_gain && (!best || gain > best_gain)) {
      best_gain = gain;
      best = PlannedScan{i, now_s, *position_(i, now_s)};
    }
  }
  return best;
}

double SessionPlanner::look_again_s(double now_s) const {
  double at = now_s + settings_.wait_s;
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    const auto& last = last_fitted_s_[i];
    if (!by_period(i) || !last) continue;
    const double due_s = *last + settings_.every_s;
    if (due_s > now_s) at = std::min(at, due_s);
  }
  return at;
}

void SessionPlanner::scanned(std::size_t index, double started_s, double ended_s, bool fitted) {
  if (index >= sources_.size()) return;
  if (fitted) {
    last_fitted_s_[index] = started_s;
    ++fitted_;
  } else {
    last_failed_s_[index] = ended_s;
  }
}

void SessionPlanner::covered(const control::AzEl& at, bool xel, bool el) {
  coverage_.add(at, 1.0, xel, el);
}

std::optional<control::AzEl> SessionPlanner::position(std::size_t index, double t_s) const {
  if (index >= sources_.size()) return std::nullopt;
  return position_(index, t_s);
}

std::optional<std::size_t> SessionPlanner::find(const std::string& name) const {
  for (std::size_t i = 0; i < sources_.size(); ++i) {
    if (sources_[i].name == name) return i;
  }
  return std::nullopt;
}

std::vector<PlannedScan> plan_session(SessionPlanner planner, double start_s, double end_s) {
  std::vector<PlannedScan> out;
  const double scan_s = planner.settings().scan_s;
  double t = start_s;
  while (t + scan_s <= end_s && !planner.done()) {
    const auto scan = planner.next(t);
    if (!scan) {
      t = planner.look_again_s(t);
      continue;
    }
    out.push_back(*scan);
    // As a session would log it: where the source was halfway through its scans.
    planner.covered(planner.position(scan->source, t + 0.5 * scan_s).value_or(scan->at), true,
                    true);
    planner.scanned(scan->source, t, t + scan_s, true);
    t += scan_s;
  }
  return out;
}

}  // namespace azt::calibration
