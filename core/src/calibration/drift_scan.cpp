#include "azt/calibration/drift_scan.hpp"

#include <cmath>

#include "azt/calibration/scan_plan.hpp"
#include "azt/util/format_number.hpp"

namespace azt::calibration {
namespace {

/// The source must still be this many beamwidths away when the recording starts: the baseline
/// before the peak needs them.
constexpr double kMinLeadBeams = 1.5;
constexpr double kStillS = 0.25;  ///< as a scan's points (scan_session.hpp)

bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

Result<bool> check_spec(const DriftSpec& s, double rate_deg_s) {
  if (!(s.beamwidth_deg > 0.0 && s.beamwidth_deg <= ScanSpec::kMaxBeamwidthDeg)) {
    return fail("beamwidth_deg: must be in (0, 30]");
  }
  if (!in(s.ahead_beams, 1.5, 10.0)) return fail("ahead_beams: must be in [1.5, 10]");
  if (!in(s.slew_s, 0.0, 3600.0)) return fail("slew_s: must be in [0, 3600] s");
  if (!in(s.settle_s, 0.0, 60.0)) return fail("settle_s: must be in [0, 60] s");
  if (!in(s.bin_s, 0.2, 60.0)) return fail("bin_s: must be in [0.2, 60] s");
  if (!(std::isfinite(rate_deg_s) && rate_deg_s > 1e-5)) {
    return fail("the source's rate must be above 1e-5 °/s (a source at the pole does not drift)");
  }
  const double lead_s = s.ahead_beams * s.beamwidth_deg / rate_deg_s;
  const double minutes = (s.slew_s + 2.0 * lead_s) / 60.0;
  if (minutes * 60.0 > DriftSpec::kMaxDurationS) {
    return fail("the source drifts too slowly: the drift would take " + format_fixed(minutes, 0) +
                " minutes (at most 240)");
  }
  return true;
}

}  // namespace

Result<DriftScan> DriftScan::start(const DriftSpec& spec, double rate_deg_s, double now_s) {
  if (auto ok = check_spec(spec, rate_deg_s); !ok) return ok.error();
  return DriftScan(spec, rate_deg_s, now_s);
}

DriftScan::DriftScan(const DriftSpec& spec, double rate_deg_s, double now_s)
    : spec_(spec), rate_deg_s_(rate_deg_s) {
  const double lead_s = spec.ahead_beams * spec.beamwidth_deg / rate_deg_s;
  transit_s_ = now_s + spec.slew_s + lead_s;
  end_s_ = transit_s_ + lead_s;
}

void DriftScan::tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
                     const std::optional<SkyOffset>& source_from_beam) {
  if (done()) return;
  const bool unchanged = encoders && last_encoders_ && encoders->az_deg == last_encoders_->az_deg &&
                         encoders->el_deg == last_encoders_->el_deg;
  if (!unchanged || driving) still_since_s_.reset();
  if (unchanged && !driving && !still_since_s_) still_since_s_ = now_s;
  if (!unchanged) last_encoders_ = encoders;
  still_ = still_since_s_ && now_s - *still_since_s_ >= kStillS;
  // The bins keep the beam relative to the source (drift_fit.hpp): the other way round.
  pointed_.reset();
  if (source_from_beam) pointed_ = SkyOffset{-source_from_beam->xel_deg, -source_from_beam->el_deg};
  if (phase_ == DriftPhase::Slewing) {
    const double latest_s = transit_s_ - kMinLeadBeams * spec_.beamwidth_deg / rate_deg_s_;
    if (now_s > latest_s) {
      phase_ = DriftPhase::Failed;
      reason_ =
          "the antenna did not stand still on the point in time: the source was already "
          "within 1.5 beamwidths of it";
    } else if (still_since_s_ && now_s - *still_since_s_ >= spec_.settle_s) {
      begin_recording(now_s);
    }
  } else if (phase_ == DriftPhase::Recording && now_s >= end_s_) {
    close_bin();
    phase_ = DriftPhase::Done;
  }
}

void DriftScan::begin_recording(double now_s) {
  phase_ = DriftPhase::Recording;
  record_start_s_ = now_s;
  bin_index_ = 0;
  open_ = DriftBin{};
}

bool DriftScan::reading(double now_s, double power_db) {
  if (phase_ != DriftPhase::Recording || !still_ || !pointed_ || !std::isfinite(power_db)) {
    return false;
  }
  const auto index = static_cast<std::size_t>(std::floor((now_s - record_start_s_) / spec_.bin_s));
  if (index != bin_index_) {
    close_bin();
    bin_index_ = index;
  }
  open_.t_s += now_s;
  open_.power += std::pow(10.0, power_db / 10.0);
  open_.pointed.xel_deg += pointed_->xel_deg;
  open_.pointed.el_deg += pointed_->el_deg;
  ++open_.readings;
  return true;
}

void DriftScan::close_bin() {
  if (open_.readings > 0) {
    const double n = open_.readings;
    bins_.push_back({open_.t_s / n, open_.power / n,
                     SkyOffset{open_.pointed.xel_deg / n, open_.pointed.el_deg / n},
                     open_.readings});
  }
  open_ = DriftBin{};
}

Result<DriftFit> DriftScan::fit() const {
  if (phase_ == DriftPhase::Failed) return fail(reason_);
  if (phase_ != DriftPhase::Done) return fail("the drift has not finished");
  return fit_drift(bins_, spec_.beamwidth_deg);
}

}  // namespace azt::calibration
