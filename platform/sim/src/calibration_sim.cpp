#include "azt/sim/calibration_sim.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "azt/calibration/scan_session.hpp"
#include "azt/sim/station_loop.hpp"

namespace azt::sim {
namespace {

using calibration::ScanKind;
using calibration::ScanPoint;
using calibration::ScanSample;
using calibration::SkyOffset;
using control::AzEl;

constexpr double kIdleStepS = 600.0;  ///< nothing to scan: wait this long and look again

double wrap_180(double deg) { return std::remainder(deg, 360.0); }

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

  [[nodiscard]] const SimulatedReceiver& receiver() const { return receiver_; }

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

struct ScanOutcome {
  Result<calibration::ScanFit> fit = fail("not scanned");
  AzEl sky_xel;  ///< the source when the cross-elevation line's readings centre
  AzEl sky_el;   ///< and when the elevation line's do
};

/// One scan of `source` about `centre`, as the daemon runs it (calibration::ScanSession).
ScanOutcome run_scan(ScanBench& bench, const CalibrationSimSetup& setup,
                     const CalibrationSource& source, const calibration::ScanSpec& spec,
                     SkyOffset centre) {
  calibration::ScanTiming timing;
  timing.settle_s = setup.settle_s;
  timing.dwell_s = setup.dwell_s;
  auto session = calibration::ScanSession::start(spec, timing, centre, bench.now());
  if (!session) return {session.error(), {}, {}};
  bench.run(session.value(), source);
  ScanOutcome out;
  out.fit = session->fit();
  const auto at = [&source](std::optional<double> t) {
    return t ? source.track(*t).value_or(AzEl{}) : AzEl{};
  };
  out.sky_xel = at(session->xel_moment_s());
  out.sky_el = at(session->el_moment_s());
  return out;
}

calibration::ScanSpec scan_spec(const CalibrationSimSetup& setup, ScanKind kind) {
  calibration::ScanSpec spec;
  spec.kind = kind;
  spec.beamwidth_deg = setup.receiver.beamwidth_deg;
  spec.points_per_line = kind == ScanKind::Raster ? 7 : setup.points_per_line;
  spec.half_span_beams = kind == ScanKind::Raster ? 3.0 : setup.half_span_beams;
  return spec;
}

/// Cross scan; if it finds nothing, a raster a beamwidth apart to find the source; then a
/// cross scan there and back centred on what was found, whose result is kept.
ScanRecord scan_source(ScanBench& bench, const CalibrationSimSetup& setup,
                       const CalibrationSource& source) {
  ScanRecord rec;
  rec.source = source.name;
  ScanOutcome first = run_scan(bench, setup, source, scan_spec(setup, ScanKind::Cross), {});
  rec.scans = 1;
  if (!first.fit) {
    first = run_scan(bench, setup, source, scan_spec(setup, ScanKind::Raster), {});
    ++rec.scans;
  }
  if (!first.fit) {
    rec.refused = first.fit.error().message;
    rec.t_s = bench.now();
    return rec;
  }
  ScanOutcome refine =
      run_scan(bench, setup, source, scan_spec(setup, ScanKind::Cross), first.fit->peak);
  ++rec.scans;
  rec.t_s = bench.now();
  rec.sky_xel = refine.sky_xel;
  rec.sky = refine.sky_el;
  if (refine.fit) {
    rec.fit = *refine.fit;
  } else {
    rec.refused = refine.fit.error().message;
  }
  return rec;
}

/// The scan (and the source's drift while it runs, at most kDriftDeg of azimuth) stays clear of
/// the azimuth stops: a scan across the stop of a 0–360° rotator would unwind a whole turn.
bool clear_of_stops(const CalibrationSimSetup& setup, const AzEl& at) {
  constexpr double kDriftDeg = 15.0;
  const control::AzimuthRange& range = setup.station.station.az_range;
  const double cos_el = std::max(std::cos(at.el_deg * 3.14159265358979323846 / 180.0), 0.05);
  const double margin =
      setup.half_span_beams * setup.receiver.beamwidth_deg * 2.0 / cos_el + kDriftDeg;
  if (range.max_deg - range.min_deg >= 360.0 + 2.0 * margin) return true;
  const double az = range.min_deg + std::fmod(at.az_deg - range.min_deg + 720.0, 360.0);
  return az - range.min_deg >= margin && range.max_deg - az >= margin;
}

/// The source to scan next: up, bright enough, clear of the others and of the azimuth stops, and
/// farthest from the directions already scanned (so the scans spread over the sky).
const CalibrationSource* next_source(const CalibrationSimSetup& setup, const ScanBench& bench,
                                     const std::vector<ScanRecord>& done) {
  const double t = bench.now();
  const std::vector<RadioEmitter> sky = bench.sky_at(t);
  const CalibrationSource* best = nullptr;
  double best_gap = -1.0;
  for (const CalibrationSource& s : setup.sources) {
    const auto at = s.track(t);
    if (!at || at->el_deg < setup.min_el_deg || at->el_deg > setup.max_el_deg) continue;
    if (!clear_of_stops(setup, *at)) continue;
    if (bench.receiver().peak_rise_db({*at, s.peak_k, s.size_deg}) < setup.min_rise_db) continue;
    const bool confused = std::any_of(sky.begin(), sky.end(), [&](const RadioEmitter& e) {
      const double d = calibration::separation_deg(e.sky, *at);
      return d > 1e-9 && d < 4.0 * setup.receiver.beamwidth_deg &&
             bench.receiver().peak_rise_db(e) > 0.1;
    });
    if (confused) continue;
    double gap = std::numeric_limits<double>::infinity();
    for (const ScanRecord& r : done) {
      if (r.fit) gap = std::min(gap, calibration::separation_deg(r.sky, *at));
    }
    if (gap > best_gap) {
      best_gap = gap;
      best = &s;
    }
  }
  return best;
}

/// The mount's angles at which the beam was on the source at `sky`, from the offset the scan
/// found: the controller believed the beam at source + peak; undo the user correction it
/// subtracts and the model it applied.
AzEl mount_on_source(const CalibrationSimSetup& setup, const AzEl& sky, const SkyOffset& peak) {
  const auto& corrections = setup.station.station.corrections;
  AzEl believed = calibration::apply_offset(sky, peak);
  believed.az_deg += corrections.user.az_deg();
  believed.el_deg += corrections.user.el_deg();
  return calibration::mount_for_sky(believed, corrections.model).value_or(believed);
}

/// A scan's two lines, each at its own moment.
void add_observations(const CalibrationSimSetup& setup, const ScanRecord& rec,
                      std::vector<calibration::PointingObservation>& out) {
  const SkyOffset& sigma = rec.fit->peak_std;
  out.push_back(
      {mount_on_source(setup, rec.sky_xel, rec.fit->peak), rec.sky_xel, true, false, sigma});
  out.push_back({mount_on_source(setup, rec.sky, rec.fit->peak), rec.sky, false, true, sigma});
}

}  // namespace

CalibrationSimResult simulate_calibration(const CalibrationSimSetup& setup) {
  ScanBench bench(setup);
  CalibrationSimResult result;
  while (result.scans.size() < setup.max_scans && bench.now() < setup.duration_s) {
    const CalibrationSource* source = next_source(setup, bench, result.scans);
    if (source == nullptr) {
      bench.idle(kIdleStepS);
      continue;
    }
    result.scans.push_back(scan_source(bench, setup, *source));
  }
  std::vector<calibration::PointingObservation> obs;
  for (const ScanRecord& r : result.scans) {
    if (r.fit) add_observations(setup, r, obs);
  }
  const calibration::PointingTerms& in_use = setup.station.station.corrections.model;
  auto fit = calibration::fit_pointing_model(obs, in_use);
  if (fit) {
    result.fit = *fit;
  } else {
    result.fit_refused = fit.error().message;
  }
  const calibration::PointingTerms& truth = setup.station.plant.pointing_errors;
  result.before = calibration::beam_error_over_sky(truth, in_use);
  result.after = calibration::beam_error_over_sky(truth, fit ? fit->terms : in_use);
  result.faults = bench.faults();
  result.simulated_s = bench.now();
  return result;
}

ScanRecord simulate_single_scan(const CalibrationSimSetup& setup, const CalibrationSource& source) {
  ScanBench bench(setup);
  return scan_source(bench, setup, source);
}

}  // namespace azt::sim
