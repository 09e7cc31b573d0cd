#include "azt/calibration/calibration_session.hpp"

#include <utility>

namespace azt::calibration {

CalibrationSession::CalibrationSession(SessionPlanner planner, const SessionSetup& setup,
                                       const std::vector<ScanLogEntry>& earlier)
    : planner_(std::move(planner)), setup_(setup) {
  resume(earlier);
}

void CalibrationSession::resume(const std::vector<ScanLogEntry>& earlier) {
  const double epoch_s = setup_.epoch.unix_seconds();
  for (const ScanLogEntry& row : earlier) {
    log_.push_back(row);
    if (!(row.weight > 0.0)) continue;
    planner_.covered({row.az_deg, row.el_deg}, row.measured != Measured::El,
                     row.measured != Measured::Az);
    // A scan's last row (a cross scan's elevation line, or its only one) counts it as scanned.
    const auto index = planner_.find(row.source);
    if (index && row.measured != Measured::Az) {
      const double t_s = row.utc.unix_seconds() - epoch_s;
      planner_.scanned(*index, t_s, t_s, true);
    }
  }
}

ScanSpec CalibrationSession::search_spec(const ScanSpec& spec) {
  ScanSpec s = spec;
  s.kind = ScanKind::Raster;
  s.points_per_line = 7;
  s.half_span_beams = 3.0;
  return s;
}

SessionStep CalibrationSession::scan_step() const {
  SessionStep step;
  step.kind = SessionStep::Kind::Scan;
  step.source = current_.source;
  step.spec = spec_;
  step.centre = centre_;
  return step;
}

double CalibrationSession::expected_source_s(const SessionSetup& setup) {
  constexpr double kMoveS = 1.0;
  const auto plan = plan_scan(setup.spec);
  if (!plan) return 0.0;
  const double points = static_cast<double>(measuring_order(setup.spec.kind, *plan).size());
  const double per_point =
      setup.timing.settle_s + setup.timing.dwell_s + ScanSession::kStillS + kMoveS;
  return (setup.refine ? 2.0 : 1.0) * points * per_point;
}

bool CalibrationSession::begin(std::size_t index, double now_s) {
  if (phase_ != Phase::Idle || index >= planner_.sources().size()) return false;
  current_ = SourceScans{};
  current_.source = index;
  current_.name = planner_.sources()[index].name;
  current_.started_s = now_s;
  phase_ = Phase::First;
  spec_ = setup_.spec;
  centre_ = {};
  return true;
}

SessionStep CalibrationSession::next(double now_s) {
  if (phase_ != Phase::Idle) return scan_step();
  SessionStep step;
  if (planner_.done()) {
    step.kind = SessionStep::Kind::Done;
    return step;
  }
  const auto planned = planner_.next(now_s);
  if (!planned) {
    step.kind = SessionStep::Kind::Wait;
    step.until_s = planner_.look_again_s(now_s);
    return step;
  }
  begin(planned->source, now_s);
  return scan_step();
}

std::vector<ScanLogEntry> CalibrationSession::scan_ended(double now_s, const ScanResult& result) {
  if (phase_ == Phase::Idle) return {};
  ++current_.scans;
  const bool found = result.fit.ok();
  if (phase_ == Phase::Refine) return finish(now_s, result);
  if (phase_ == Phase::First && !found && spec_.kind != ScanKind::Raster) {
    phase_ = Phase::Search;
    spec_ = search_spec(setup_.spec);
    return {};
  }
  if (found && setup_.refine) {
    phase_ = Phase::Refine;
    spec_ = setup_.spec;
    centre_ = result.fit->peak;
    return {};
  }
  return finish(now_s, result);
}

std::vector<ScanLogEntry> CalibrationSession::finish(double now_s, const ScanResult& result) {
  phase_ = Phase::Idle;
  current_.ended_s = now_s;
  const bool placed = result.sky_xel && result.sky_el && result.xel_moment_s && result.el_moment_s;
  if (!result.fit) {
    current_.refused = result.fit.error().message;
  } else if (!placed) {
    current_.refused = "the source's position at the scan's moments is unknown";
  }
  std::vector<ScanLogEntry> rows;
  if (result.fit && placed) {
    current_.fit = *result.fit;
    current_.sky_xel = *result.sky_xel;
    current_.sky_el = *result.sky_el;
    const PlanSource& source = planner_.sources()[current_.source];
    const FinishedScan scan{source.name,
                            spec_.kind,
                            *result.fit,
                            *result.sky_xel,
                            *result.sky_el,
                            astro::utc_plus(setup_.epoch, *result.xel_moment_s),
                            astro::utc_plus(setup_.epoch, *result.el_moment_s),
                            source.size_deg};
    rows = log_entries(scan, setup_.corrections);
    for (const ScanLogEntry& row : rows) {
      planner_.covered({row.az_deg, row.el_deg}, row.measured != Measured::El,
                       row.measured != Measured::Az);
      log_.push_back(row);
    }
  }
  planner_.scanned(current_.source, current_.started_s, now_s, !rows.empty());
  history_.push_back(current_);
  return rows;
}

}  // namespace azt::calibration
