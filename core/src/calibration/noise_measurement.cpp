#include "azt/calibration/noise_measurement.hpp"

#include <cmath>
#include <string>

namespace azt::calibration {
namespace {

Result<bool> check_plan(const NoisePlan& p, const ScanTiming& t) {
  if (!(p.beamwidth_deg > 0.0 && p.beamwidth_deg <= ScanSpec::kMaxBeamwidthDeg)) {
    return fail("beamwidth_deg: must be in (0, 30]");
  }
  if (!(p.offset_beams >= NoisePlan::kMinOffsetBeams &&
        p.offset_beams <= NoisePlan::kMaxOffsetBeams)) {
    return fail("offset_beams: must be in [2, 20] beamwidths");
  }
  if (p.repeats < NoisePlan::kMinRepeats || p.repeats > NoisePlan::kMaxRepeats) {
    return fail("repeats: must be 2 to 50");
  }
  if (!(std::isfinite(p.centre.xel_deg) && std::isfinite(p.centre.el_deg))) {
    return fail("centre: must be finite");
  }
  if (!(t.settle_s >= 0.0 && t.dwell_s > 0.0 && t.max_settle_s > 0.0)) {
    return fail("settle_s must be ≥ 0, dwell_s and max_settle_s above 0");
  }
  return true;
}

/// On, off on one side, on, off on the other side, … (header).
std::vector<NoiseStep> plan_steps(const NoisePlan& p) {
  std::vector<NoiseStep> steps;
  const double off_deg = p.offset_beams * p.beamwidth_deg;
  for (std::size_t k = 0; k < p.repeats; ++k) {
    const int side = k % 2 == 0 ? 1 : -1;
    steps.push_back({true, 0, p.centre, std::nullopt, 0});
    steps.push_back({false, side, SkyOffset{p.centre.xel_deg + side * off_deg, p.centre.el_deg},
                     std::nullopt, 0});
  }
  return steps;
}

double linear(double db) { return std::pow(10.0, db / 10.0); }

/// Mean and standard error of the mean.
void mean_and_error(const std::vector<double>& v, double& mean, double& std_error) {
  const double n = static_cast<double>(v.size());
  double sum = 0.0;
  for (double x : v) sum += x;
  mean = sum / n;
  double squares = 0.0;
  for (double x : v) squares += (x - mean) * (x - mean);
  std_error = std::sqrt(squares / (n - 1.0)) / std::sqrt(n);
}

}  // namespace

Result<NoiseMeasurement> NoiseMeasurement::start(const NoisePlan& plan, const ScanTiming& timing,
                                                 double now_s) {
  if (auto ok = check_plan(plan, timing); !ok) return ok.error();
  return NoiseMeasurement(plan, timing, now_s);
}

NoiseMeasurement::NoiseMeasurement(const NoisePlan& plan, const ScanTiming& timing, double now_s)
    : plan_(plan), timing_(timing), steps_(plan_steps(plan)), dwell_(timing, now_s) {}

std::optional<SkyOffset> NoiseMeasurement::offset() const {
  if (done()) return std::nullopt;
  return steps_[index_].offset;
}

void NoiseMeasurement::tick(double now_s, bool driving,
                            const std::optional<control::AzEl>& encoders) {
  if (done()) return;
  dwell_.tick(now_s, driving, encoders);
  if (!dwell_.finished()) return;
  steps_[index_].power_db = dwell_.mean_db();
  steps_[index_].readings = dwell_.readings();
  ++index_;
  dwell_ = PointDwell(timing_, now_s);
}

bool NoiseMeasurement::reading(double power_db) { return !done() && dwell_.reading(power_db); }

Result<NoiseResult> NoiseMeasurement::result() const {
  NoiseResult r;
  double on_sum = 0.0, off_sum = 0.0;
  for (std::size_t i = 0; i + 1 < steps_.size(); i += 2) {
    const NoiseStep& on = steps_[i];
    const NoiseStep& off = steps_[i + 1];
    r.missed += (on.power_db ? 0U : 1U) + (off.power_db ? 0U : 1U);
    if (!on.power_db || !off.power_db) continue;
    r.pair_y_db.push_back(*on.power_db - *off.power_db);
    on_sum += linear(*on.power_db);
    off_sum += linear(*off.power_db);
  }
  const std::size_t pairs = r.pair_y_db.size();
  if (pairs < NoisePlan::kMinRepeats) {
    return fail("too few on/off pairs read: " + std::to_string(pairs) + " of " +
                std::to_string(steps_.size() / 2) + " (" + std::to_string(r.missed) +
                " pointings missed; at least 2 needed)");
  }
  mean_and_error(r.pair_y_db, r.y_db, r.std_error_db);
  r.on_db = 10.0 * std::log10(on_sum / static_cast<double>(pairs));
  r.off_db = 10.0 * std::log10(off_sum / static_cast<double>(pairs));
  return r;
}

}  // namespace azt::calibration
