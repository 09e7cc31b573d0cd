#include "station/pointing_scanner.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "azt/calibration/pointing_model.hpp"

namespace azt::app {
namespace {

/// One line's fitted curve, linear power (scan_fit.hpp LineCurve): the console draws it.
nlohmann::json curve_json(const calibration::LineCurve& c) {
  return {{"baseline", c.baseline}, {"slope", c.slope}, {"amplitude", c.amplitude}};
}

}  // namespace

Result<bool> PointingScanner::ready(double now_s) const {
  if (feed_ == nullptr) return fail("no receiver: set [receiver] to scan");
  if (feed_->stale(now_s)) return fail("the receiver is silent: no reading to scan with");
  return true;
}

Result<bool> PointingScanner::start(const std::string& source, const calibration::ScanSpec& spec,
                                    const calibration::ScanTiming& timing, double now_s,
                                    const calibration::SkyOffset& centre) {
  if (auto ok = ready(now_s); !ok) return ok;
  auto session = calibration::ScanSession::start(spec, timing, centre, now_s);
  if (!session) return session.error();
  session_ = std::move(session).value();
  last_.reset();
  source_ = source;
  state_ = "running";
  reason_.clear();
  last_reading_s_ = now_s;
  sky_xel_.reset();
  sky_el_.reset();
  fit_.reset();
  found_.reset();
  return true;
}

void PointingScanner::stop(const std::string& why) {
  if (!session_) return;
  last_ = std::move(session_);
  session_.reset();
  state_ = "stopped";
  reason_ = why;
}

std::optional<control::AzEl> PointingScanner::aim(const control::AzEl& source_now) const {
  if (!session_) return std::nullopt;
  const auto offset = session_->offset();
  if (!offset) return std::nullopt;
  return calibration::apply_offset(source_now, *offset);
}

void PointingScanner::tick(double now_s, bool driving, const std::optional<control::AzEl>& encoders,
                           const std::optional<control::AzEl>& source_now,
                           const std::optional<control::AzEl>& believed) {
  if (!session_) return;
  std::optional<calibration::SkyOffset> pointed;
  if (source_now && believed) pointed = calibration::offset_between(*source_now, *believed);
  const bool had_xel = session_->xel_moment_s().has_value();
  const bool had_el = session_->el_moment_s().has_value();
  session_->tick(now_s, driving, encoders, pointed);
  if (!had_xel && session_->xel_moment_s()) sky_xel_ = source_now;
  if (!had_el && session_->el_moment_s()) sky_el_ = source_now;
  // The readings that arrived since the last tick (oldest first), each passed on once.
  const std::vector<calibration::PowerReading> fresh = feed_->readings_since(last_reading_s_);
  for (const calibration::PowerReading& r : fresh) {
    if (r.t_s > last_reading_s_) session_->reading(r.t_s, r.power_db);
  }
  if (!fresh.empty()) last_reading_s_ = fresh.back().t_s;
  if (session_->done()) finish();
}

void PointingScanner::finish() {
  last_ = std::move(session_);
  session_.reset();
  auto fit = last_->fit();
  if (!fit) {
    state_ = "refused";
    reason_ = fit.error().message;
    return;
  }
  state_ = "done";
  fit_ = *fit;
  if (sky_xel_ && sky_el_) {
    const control::AzEl at_xel = calibration::apply_offset(*sky_xel_, fit->peak);
    const control::AzEl at_el = calibration::apply_offset(*sky_el_, fit->peak);
    found_ = ScanOffsets{std::remainder(at_xel.az_deg - sky_xel_->az_deg, 360.0),
                         at_el.el_deg - sky_el_->el_deg};
  }
}

std::optional<ScanOffsets> PointingScanner::found() const { return found_; }

calibration::ScanResult PointingScanner::result() const {
  calibration::ScanResult r;
  if (!last_) return r;
  if (fit_) {
    r.fit = *fit_;
  } else {
    r.fit = fail(reason_.empty() ? std::string("no fit") : reason_);
  }
  r.xel_moment_s = last_->xel_moment_s();
  r.el_moment_s = last_->el_moment_s();
  r.sky_xel = sky_xel_;
  r.sky_el = sky_el_;
  return r;
}

nlohmann::json PointingScanner::to_json() const {
  using nlohmann::json;
  const calibration::ScanSession* s = session_ ? &*session_ : (last_ ? &*last_ : nullptr);
  json j{{"state", state_}, {"source", source_}, {"reason", reason_}};
  if (s == nullptr) return j;
  j["kind"] = std::string(calibration::to_string(s->spec().kind));
  j["beamwidth_deg"] = s->spec().beamwidth_deg;
  j["points_done"] = s->points_done();
  j["points_total"] = s->points_total();
  json samples = json::array();
  for (const calibration::ScanSample& sample : s->samples()) {
    const calibration::SkyOffset at = sample.pointed.value_or(sample.point.offset);
    samples.push_back({{"xel_deg", at.xel_deg},
                       {"el_deg", at.el_deg},
                       {"line", sample.point.offset.el_deg == 0.0 ? "xel" : "el"},
                       {"planned_xel_deg", sample.point.offset.xel_deg},
                       {"planned_el_deg", sample.point.offset.el_deg},
                       {"reference", sample.point.reference},
                       {"power_db", sample.power_db ? json(*sample.power_db) : json(nullptr)}});
  }
  j["samples"] = samples;
  if (fit_) {
    j["fit"] = {{"xel_offset_deg", fit_->peak.xel_deg},
                {"el_offset_deg", fit_->peak.el_deg},
                {"xel_std_deg", fit_->peak_std.xel_deg},
                {"el_std_deg", fit_->peak_std.el_deg},
                {"width_xel_deg", fit_->width_xel_deg},
                {"width_el_deg", fit_->width_el_deg},
                {"peak_db", fit_->peak_db},
                {"noise_db", fit_->noise_db},
                {"used", fit_->used},
                {"missing", fit_->missing},
                {"xel_curve", curve_json(fit_->xel_curve)},
                {"el_curve", curve_json(fit_->el_curve)}};
  }
  if (found_) {
    j["found"] = {{"az_offset_deg", found_->az_offset_deg},
                  {"el_offset_deg", found_->el_offset_deg}};
  }
  return j;
}

}  // namespace azt::app
