#include "azt/sim/calibration_sim.hpp"

#include <algorithm>
#include <cmath>

#include "azt/calibration/calibration_session.hpp"
#include "azt/calibration/scan_session.hpp"
#include "azt/calibration/source_snr.hpp"
#include "azt/proto/hub_reading.hpp"
#include "azt/sim/station_loop.hpp"

namespace azt::sim {
namespace {

using calibration::ScanKind;
using calibration::ScanPoint;
using calibration::ScanSample;
using calibration::SkyOffset;
using control::AzEl;

double wrap_180(double deg) { return std::remainder(deg, 360.0); }

calibration::ScanTiming timing(const CalibrationSimSetup& setup) {
  calibration::ScanTiming t;
  t.settle_s = setup.settle_s;
  t.dwell_s = setup.dwell_s;
  return t;
}

/// The daemon's station, the plants and the receiver, stepped together in virtual time.
class ScanBench {
 public:
  explicit ScanBench(const CalibrationSimSetup& setup)
      : setup_(setup), loop_(setup.station, nullptr), receiver_(setup.receiver) {}

  [[nodiscard]] double now() const { return t_; }
  std::vector<std::string>& faults() { return faults_; }

  /// One control tick towards `demand` (nullopt: hold).
  void step(const std::optional<AzEl>& demand, const AzEl& rate) {
    loop_.tick(t_, demand, rate);
    loop_.collect_faults(faults_, t_);
    t_ += setup_.station.station.tick_s;
  }

  void idle(double seconds) {
    const double until = t_ + seconds;
    while (t_ < until) step(std::nullopt, AzEl{});
  }

  /// Runs `session` to its end on `source`: the station follows source + the session's offset
  /// every tick, the receiver reads at its rate.
  void run(calibration::ScanSession& session, const CalibrationSource& source) {
    const double period = 1.0 / setup_.receiver.rate_hz;
    double next_reading = t_ + period;
    while (!session.done()) {
      follow(source, *session.offset());
      const auto src = source.track(t_);
      const auto believed = loop_.station().sky_position(t_);
      std::optional<SkyOffset> pointed;
      if (src && believed) pointed = calibration::offset_between(*src, *believed);
      const bool driving = loop_.station().az().moving || loop_.station().el().moving;
      session.tick(t_, driving, loop_.station().encoder_reading(), pointed);
      if (t_ >= next_reading) {
        session.reading(t_, receiver_.read_db(true_beam(), sky_at(t_)));
        next_reading += period;
      }
    }
  }

  /// The emitters at `t_s`.
  [[nodiscard]] std::vector<RadioEmitter> sky_at(double t_s) const {
    std::vector<RadioEmitter> out;
    for (const CalibrationSource& s : setup_.sources) {
      if (const auto at = s.track(t_s)) out.push_back({*at, s.peak_k, s.size_deg});
    }
    return out;
  }

 private:
  void follow(const CalibrationSource& source, const SkyOffset& off) {
    const auto here = source.track(t_);
    const auto ahead = source.track(t_ + 1.0);
    if (!here) {
      step(std::nullopt, AzEl{});
      return;
    }
    const AzEl demand = calibration::apply_offset(*here, off);
    AzEl rate{};
    if (ahead) {
      const AzEl next = calibration::apply_offset(*ahead, off);
      rate = {wrap_180(next.az_deg - demand.az_deg), next.el_deg - demand.el_deg};
    }
    step(demand, rate);
  }

  /// Where the beam really is: the plants' shafts through the mount's errors.
  [[nodiscard]] AzEl true_beam() const {
    const auto& offsets = setup_.station.station.corrections.offsets;
    const AzEl mount{loop_.az_plant().shaft_deg() + offsets.az_deg,
                     loop_.el_plant().shaft_deg() + offsets.el_deg};
    return calibration::beam_on_sky(mount, setup_.station.plant.pointing_errors);
  }

  const CalibrationSimSetup& setup_;
  StationLoop loop_;
  SimulatedReceiver receiver_;
  std::vector<std::string> faults_;
  double t_ = 0.0;
};

/// One scan of `source` about `centre`, as the daemon runs it (calibration::ScanSession).
calibration::ScanResult run_scan(ScanBench& bench, const CalibrationSimSetup& setup,
                                 const CalibrationSource& source, const calibration::ScanSpec& spec,
                                 SkyOffset centre) {
  auto session = calibration::ScanSession::start(spec, timing(setup), centre, bench.now());
  calibration::ScanResult out;
  if (!session) {
    out.fit = session.error();
    return out;
  }
  bench.run(session.value(), source);
  out.fit = session->fit();
  out.xel_moment_s = session->xel_moment_s();
  out.el_moment_s = session->el_moment_s();
  if (out.xel_moment_s) out.sky_xel = source.track(*out.xel_moment_s);
  if (out.el_moment_s) out.sky_el = source.track(*out.el_moment_s);
  return out;
}

calibration::SessionSetup session_setup(const CalibrationSimSetup& setup) {
  calibration::SessionSetup s;
  s.spec.kind = ScanKind::Cross;
  s.spec.beamwidth_deg = setup.receiver.beamwidth_deg;
  s.spec.points_per_line = setup.points_per_line;
  s.spec.half_span_beams = setup.half_span_beams;
  s.timing = timing(setup);
  s.epoch = setup.epoch;
  s.corrections = setup.station.station.corrections;
  return s;
}

/// Each source with its SNR at a scan point (source_snr.hpp), from what the receiver hears.
std::vector<calibration::PlanSource> plan_sources(const CalibrationSimSetup& setup) {
  const ReceiverSetup& rx = setup.receiver;
  const calibration::DishSetup dish{rx.dish_m, rx.efficiency, rx.tsys_k, rx.beamwidth_deg};
  const calibration::PointNoise noise{rx.noise_db, setup.dwell_s * rx.rate_hz};
  std::vector<calibration::PlanSource> out;
  for (const CalibrationSource& s : setup.sources) {
    const auto e = calibration::estimate_source(s.name, s.peak_k, s.size_deg, dish, noise);
    out.push_back({s.name, e.snr_db, s.size_deg, s.name == "sun"});
  }
  return out;
}

calibration::SessionPlanner planner(const CalibrationSimSetup& setup) {
  calibration::SiteLimits limits;
  limits.min_el_deg = setup.min_el_deg;
  limits.max_el_deg = setup.max_el_deg;
  limits.az_range = setup.station.station.az_range;
  calibration::PlanSettings p;
  p.scan_s = calibration::CalibrationSession::expected_source_s(session_setup(setup));
  p.beamwidth_deg = setup.receiver.beamwidth_deg;
  p.half_span_beams = setup.half_span_beams;
  p.every_s = setup.sun_every_s;
  p.min_snr_db = setup.min_snr_db;
  p.max_scans = setup.max_scans;
  const std::vector<CalibrationSource>* sources = &setup.sources;
  const calibration::SourcePosition position = [sources](std::size_t i, double t_s) {
    return i < sources->size() ? (*sources)[i].track(t_s) : std::nullopt;
  };
  return calibration::SessionPlanner(plan_sources(setup), position, limits, p);
}

ScanRecord record_of(const calibration::SourceScans& s) {
  ScanRecord r;
  r.source = s.name;
  r.t_s = s.ended_s;
  r.sky = s.sky_el;
  r.sky_xel = s.sky_xel;
  r.fit = s.fit;
  r.refused = s.refused;
  r.scans = s.scans;
  return r;
}

/// Runs the session's steps until it is done or the time is up.
void run_session(ScanBench& bench, const CalibrationSimSetup& setup,
                 calibration::CalibrationSession& session) {
  while (bench.now() < setup.duration_s) {
    const calibration::SessionStep step = session.next(bench.now());
    if (step.kind == calibration::SessionStep::Kind::Done) return;
    if (step.kind == calibration::SessionStep::Kind::Wait) {
      bench.idle(std::max(step.until_s - bench.now(), setup.station.station.tick_s));
      continue;
    }
    const CalibrationSource& source = setup.sources.at(step.source);
    session.scan_ended(bench.now(), run_scan(bench, setup, source, step.spec, step.centre));
  }
}

calibration::EncoderSteps encoder_steps(const CalibrationSimSetup& setup) {
  return {proto::hub_resolution_deg(setup.station.plant.az.encoder_bits),
          proto::hub_resolution_deg(setup.station.plant.el.encoder_bits)};
}

}  // namespace

CalibrationSimResult simulate_calibration(const CalibrationSimSetup& setup) {
  ScanBench bench(setup);
  calibration::CalibrationSession session(planner(setup), session_setup(setup));
  run_session(bench, setup, session);
  CalibrationSimResult result;
  for (const calibration::SourceScans& s : session.history()) result.scans.push_back(record_of(s));
  result.log = session.log();
  const calibration::PointingTerms& in_use = setup.station.station.corrections.model;
  auto fit =
      calibration::fit_pointing_model(calibration::observations_from_log(result.log), in_use);
  if (fit) {
    result.fit = *fit;
  } else {
    result.fit_refused = fit.error().message;
  }
  const calibration::PointingTerms& truth = setup.station.plant.pointing_errors;
  const calibration::PointingTerms& model = fit ? fit->terms : in_use;
  result.before = calibration::beam_error_over_sky(truth, in_use);
  result.after = calibration::beam_error_over_sky(truth, model);
  result.after_with_encoders =
      calibration::beam_error_with_encoders(truth, model, encoder_steps(setup));
  result.quantisation_floor_deg = calibration::quantisation_floor_deg(encoder_steps(setup));
  result.faults = bench.faults();
  result.simulated_s = bench.now();
  return result;
}

ScanRecord simulate_single_scan(const CalibrationSimSetup& setup, const CalibrationSource& source) {
  ScanBench bench(setup);
  calibration::CalibrationSession session(planner(setup), session_setup(setup));
  // `source` is one of setup.sources (the session names sources by their index).
  const auto found = std::find_if(setup.sources.begin(), setup.sources.end(),
                                  [&source](const CalibrationSource& s) { return &s == &source; });
  if (found == setup.sources.end()) {
    ScanRecord none;
    none.source = source.name;
    none.refused = "not one of the scenario's sources";
    return none;
  }
  session.begin(static_cast<std::size_t>(found - setup.sources.begin()), bench.now());
  while (session.scanning()) {
    const calibration::SessionStep step = session.next(bench.now());
    session.scan_ended(bench.now(), run_scan(bench, setup, source, step.spec, step.centre));
  }
  return session.history().empty() ? ScanRecord{} : record_of(session.history().back());
}

}  // namespace azt::sim
