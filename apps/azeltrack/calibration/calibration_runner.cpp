#include "calibration/calibration_runner.hpp"

#include <algorithm>
#include <utility>

namespace azt::app {
namespace {

using nlohmann::json;

/// A due scan waits this long for a silent receiver before the session gives up.
constexpr double kSilentLimitS = 60.0;

calibration::SessionSetup setup_of(const CalibrationRequest& r, double epoch_unix_s,
                                   const control::PositionCorrections& corrections) {
  calibration::SessionSetup s;
  s.spec = r.spec;
  s.timing = r.timing;
  s.refine = r.refine;
  s.epoch = astro::UtcInstant::from_unix_seconds(epoch_unix_s);
  s.corrections = corrections;
  return s;
}

calibration::SessionPlanner planner_of(const CalibrationRequest& r, const SessionSky& sky,
                                       const calibration::SessionSetup& setup,
                                       double epoch_unix_s) {
  calibration::PlanSettings p;
  p.scan_s = calibration::CalibrationSession::expected_source_s(setup);
  p.beamwidth_deg = r.spec.beamwidth_deg;
  p.half_span_beams = r.spec.half_span_beams;
  p.every_s = r.sun_every_min * 60.0;
  p.max_scans = r.max_scans;
  auto at_unix = sky.at_unix;
  calibration::SourcePosition position = [at_unix, epoch_unix_s](std::size_t i, double t_s) {
    return at_unix(i, epoch_unix_s + t_s);
  };
  return {sky.sources, std::move(position), sky.limits, p};
}

}  // namespace

json log_row_json(const calibration::ScanLogEntry& row) {
  const auto optional = [](const std::optional<double>& v) { return v ? json(*v) : json(nullptr); };
  return {{"utc", astro::format_iso8601_utc(row.utc)},
          {"source", row.source},
          {"az_deg", row.az_deg},
          {"el_deg", row.el_deg},
          {"daz_deg", row.daz_deg},
          {"del_deg", row.del_deg},
          {"measured", std::string(calibration::to_string(row.measured))},
          {"snr_db", optional(row.snr_db)},
          {"beamwidth_deg", optional(row.beamwidth_deg)}};
}

Result<bool> CalibrationRunner::start(const CalibrationRequest& request, const SessionSky& sky,
                                      double now_s, double unix_s,
                                      std::optional<double> started_unix_s) {
  if (session_) return fail("a calibration session is running already");
  if (sky.sources.empty()) return fail("sources: none of them can be scanned here");
  const double started = started_unix_s.value_or(unix_s);
  epoch_unix_s_ = unix_s - now_s;
  end_unix_s_ = started + request.hours * 3600.0;
  const auto setup = setup_of(request, epoch_unix_s_, station_.corrections());
  session_.emplace(planner_of(request, sky, setup, epoch_unix_s_), setup, rows_since(started));
  request_ = request;
  state_ = "running";
  reason_.clear();
  wait_until_s_ = now_s;
  silent_since_s_ = -1.0;
  scanning_ = false;
  current_.reset();
  pointed_.reset();
  const auto ahead =
      calibration::plan_session(session_->planner(), now_s, end_unix_s_ - epoch_unix_s_);
  planned_ = std::min(request.max_scans, session_->planner().fitted_scans() + ahead.size());
  station_.keep({{"request", request.to_json()}, {"started_unix_s", started}});
  return true;
}

std::vector<calibration::ScanLogEntry> CalibrationRunner::rows_since(double unix_s) const {
  std::vector<calibration::ScanLogEntry> out;
  for (const calibration::ScanLogEntry& row : log_) {
    if (row.utc.unix_seconds() >= unix_s) out.push_back(row);
  }
  return out;
}

void CalibrationRunner::stop(const std::string& why) {
  if (!session_) return;
  if (scanning_ && scanner_.running()) scanner_.stop(why);
  finish("stopped", why);
}

void CalibrationRunner::finish(const std::string& state, const std::string& why) {
  if (session_) done_ = session_->planner().fitted_scans();
  session_.reset();
  scanning_ = false;
  current_.reset();
  pointed_.reset();
  state_ = state;
  reason_ = why;
  station_.keep(json(nullptr));
}

void CalibrationRunner::tick(double now_s) {
  if (!session_) return;
  if (scanning_) {
    if (scanner_.running()) return;
    scan_ended(now_s);
    if (!session_) return;
  }
  if (pointed_ && station_.tracked() != pointed_) {
    return finish("stopped", "stopped: the station was given another command");
  }
  if (epoch_unix_s_ + now_s >= end_unix_s_) return finish("done", "the session's hours are over");
  if (now_s < wait_until_s_) return;
  const calibration::SessionStep step = session_->next(now_s);
  switch (step.kind) {
    case calibration::SessionStep::Kind::Done:
      return finish("done", "the session's scans are all in");
    case calibration::SessionStep::Kind::Wait:
      wait_until_s_ = step.until_s;
      return;
    case calibration::SessionStep::Kind::Scan:
      return begin_scan(step, now_s);
  }
}

void CalibrationRunner::scan_ended(double now_s) {
  scanning_ = false;
  current_.reset();
  // Another command (STOP, a target, a PC program) or a fault took the station: the operator's.
  if (scanner_.state() == "stopped") {
    return finish("stopped", scanner_.to_json().value("reason", std::string("stopped")));
  }
  const std::vector<calibration::ScanLogEntry> rows =
      session_->scan_ended(now_s, scanner_.result());
  if (rows.empty()) return;
  log_.insert(log_.end(), rows.begin(), rows.end());
  station_.append(rows);
}

void CalibrationRunner::begin_scan(const calibration::SessionStep& step, double now_s) {
  // A receiver silent for a while (the daemon just started, rtl_power restarting) is waited for.
  if (auto ready = scanner_.ready(now_s); !ready) {
    if (silent_since_s_ < 0.0) silent_since_s_ = now_s;
    if (now_s - silent_since_s_ > kSilentLimitS) {
      return finish("stopped", "stopped: " + ready.error().message);
    }
    wait_until_s_ = now_s + 1.0;
    return;
  }
  silent_since_s_ = -1.0;
  const std::string& name = session_->planner().sources().at(step.source).name;
  const auto tracked = station_.point(name);
  if (!tracked) return finish("stopped", "stopped: " + tracked.error().message);
  pointed_ = *tracked;
  session_->set_corrections(station_.corrections());
  if (auto ok = scanner_.start(*tracked, step.spec, request_.timing, now_s, step.centre); !ok) {
    return finish("stopped", "stopped: " + ok.error().message);
  }
  scanning_ = true;
  current_ = step;
}

void CalibrationRunner::add_rows(const std::vector<calibration::ScanLogEntry>& rows) {
  log_.insert(log_.end(), rows.begin(), rows.end());
}

json CalibrationRunner::to_json() const {
  json last = json::array();
  const std::size_t from = log_.size() > 5 ? log_.size() - 5 : 0;
  for (std::size_t i = from; i < log_.size(); ++i) last.push_back(log_row_json(log_[i]));
  json current(nullptr);
  if (session_ && current_) {
    current = {{"source", session_->planner().sources().at(current_->source).name},
               {"kind", std::string(calibration::to_string(current_->spec.kind))}};
  }
  return {{"state", state_},
          {"reason", reason_},
          {"plan", state_ == "idle" ? json(nullptr) : request_.to_json()},
          {"scans_done", session_ ? session_->planner().fitted_scans() : done_},
          {"scans_planned", planned_},
          {"current", current},
          {"log_rows", log_.size()},
          {"last_rows", last}};
}

}  // namespace azt::app
