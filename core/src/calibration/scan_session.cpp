#include "azt/calibration/scan_session.hpp"

#include <cmath>
#include <iterator>
#include <utility>

namespace azt::calibration {

std::vector<ScanPoint> measuring_order(ScanKind kind, const std::vector<ScanPoint>& plan) {
  if (kind != ScanKind::Cross) return plan;
  const auto half = static_cast<std::ptrdiff_t>(plan.size() / 2);
  std::vector<ScanPoint> out(plan.begin(), plan.begin() + half);
  out.insert(out.end(), std::make_reverse_iterator(plan.begin() + half), plan.rend());
  out.insert(out.end(), plan.begin() + half, plan.end());
  out.insert(out.end(), plan.rbegin(), std::make_reverse_iterator(plan.begin() + half));
  return out;
}

Result<ScanSession> ScanSession::start(const ScanSpec& spec, const ScanTiming& timing,
                                       const SkyOffset& centre, double now_s) {
  if (!(timing.settle_s >= 0.0 && timing.dwell_s > 0.0 && timing.max_settle_s > 0.0)) {
    return fail("settle_s must be ≥ 0, dwell_s and max_settle_s above 0");
  }
  auto plan = plan_scan(spec);
  if (!plan) return plan.error();
  return ScanSession(spec, timing, centre, measuring_order(spec.kind, *plan), now_s);
}

ScanSession::ScanSession(const ScanSpec& spec, const ScanTiming& timing, const SkyOffset& centre,
                         std::vector<ScanPoint> points, double now_s)
    : spec_(spec),
      timing_(timing),
      centre_(centre),
      points_(std::move(points)),
      point_start_s_(now_s),
      last_tick_s_(now_s) {}

std::optional<SkyOffset> ScanSession::offset() const {
  if (done()) return std::nullopt;
  const SkyOffset& p = points_[index_].offset;
  return SkyOffset{centre_.xel_deg + p.xel_deg, centre_.el_deg + p.el_deg};
}

void ScanSession::tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
                       const std::optional<SkyOffset>& pointed) {
  if (done()) return;
  const bool unchanged = encoders && last_encoders_ && encoders->az_deg == last_encoders_->az_deg &&
                         encoders->el_deg == last_encoders_->el_deg;
  if (!unchanged || driving || !pointed) still_since_s_.reset();
  if (unchanged && !driving && pointed && !still_since_s_) still_since_s_ = now_s;
  if (!unchanged) last_encoders_ = encoders;
  pointed_ = pointed;
  still_ = still_since_s_ && now_s - *still_since_s_ >= kStillS;
  if (!dwelling_) {
    if (still_since_s_ && now_s - *still_since_s_ >= timing_.settle_s)
      dwelling_ = true;
    else if (now_s - point_start_s_ > timing_.max_settle_s)
      finish_point(now_s);  // missed
  } else {
    if (still_) dwelt_s_ += now_s - last_tick_s_;
    if (dwelt_s_ >= timing_.dwell_s ||
        now_s - point_start_s_ > timing_.max_settle_s + 3.0 * timing_.dwell_s) {
      finish_point(now_s);
    }
  }
  last_tick_s_ = now_s;
}

bool ScanSession::reading(double /*now_s*/, double power_db) {
  if (done() || !dwelling_ || !still_ || !pointed_ || !std::isfinite(power_db)) return false;
  power_sum_ += std::pow(10.0, power_db / 10.0);
  xel_sum_ += pointed_->xel_deg;
  el_sum_ += pointed_->el_deg;
  ++readings_;
  return true;
}

void ScanSession::finish_point(double now_s) {
  ScanSample sample{points_[index_], std::nullopt, std::nullopt};
  if (readings_ > 0) {
    const double n = readings_;
    sample.power_db = 10.0 * std::log10(power_sum_ / n);
    sample.pointed = SkyOffset{xel_sum_ / n, el_sum_ / n};
  }
  samples_.push_back(sample);
  ++index_;
  note_moments(now_s);
  point_start_s_ = now_s;
  dwelling_ = false;
  dwelt_s_ = 0.0;
  power_sum_ = xel_sum_ = el_sum_ = 0.0;
  readings_ = 0;
}

void ScanSession::note_moments(double now_s) {
  // A cross scan turns each line at its end (measuring_order): the xel line after the first
  // quarter of its points, the el line after the third. Other scans: the middle, for both.
  const std::size_t n = points_.size();
  const bool cross = spec_.kind == ScanKind::Cross;
  if (index_ == (cross ? n / 4 : n / 2)) xel_moment_s_ = now_s;
  if (index_ == (cross ? 3 * n / 4 : n / 2)) el_moment_s_ = now_s;
}

Result<ScanFit> ScanSession::fit() const {
  return fit_scan(spec_.kind, samples_, spec_.beamwidth_deg);
}

}  // namespace azt::calibration
