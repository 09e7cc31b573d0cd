#include "azt/sim/noise_sim.hpp"

#include "azt/calibration/scan_session.hpp"
#include "azt/sim/sky_bench.hpp"

namespace azt::sim {
namespace {

calibration::ScanTiming timing_of(const CalibrationSimSetup& setup) {
  calibration::ScanTiming t;
  t.settle_s = setup.settle_s;
  t.dwell_s = setup.dwell_s;
  return t;
}

/// A cross scan, as the daemon runs it, through the source: where the beam is on it.
Result<calibration::ScanFit> peak_up(SkyBench& bench, const CalibrationSimSetup& setup,
                                     const CalibrationSource& source) {
  calibration::ScanSpec spec;
  spec.beamwidth_deg = setup.receiver.beamwidth_deg;
  spec.points_per_line = setup.points_per_line;
  spec.half_span_beams = setup.half_span_beams;
  auto started = calibration::ScanSession::start(spec, timing_of(setup), {}, bench.now());
  if (!started) return started.error();
  calibration::ScanSession& session = started.value();
  while (!session.done()) {
    bench.follow(source, *session.offset());
    session.tick(bench.now(), bench.driving(), bench.encoders(), bench.pointed(source));
    if (const auto r = bench.reading()) session.reading(bench.now(), *r);
  }
  return session.fit();
}

void measure(SkyBench& bench, const CalibrationSource& source, calibration::NoiseMeasurement& m) {
  while (!m.done()) {
    bench.follow(source, *m.offset());
    m.tick(bench.now(), bench.driving(), bench.encoders());
    if (const auto r = bench.reading()) m.reading(*r);
  }
}

}  // namespace

NoiseSimResult simulate_noise_measurement(const CalibrationSimSetup& setup,
                                          const CalibrationSource& source,
                                          calibration::NoisePlan plan) {
  SkyBench bench(setup);
  NoiseSimResult out;
  const auto peak = peak_up(bench, setup, source);
  if (peak) {
    out.peak = *peak;
    plan.centre = peak->peak;
  } else {
    out.peak_refused = peak.error().message;
  }
  out.sky = source.track(bench.now()).value_or(control::AzEl{});
  auto m = calibration::NoiseMeasurement::start(plan, timing_of(setup), bench.now());
  if (!m) {
    out.refused = m.error().message;
  } else {
    measure(bench, source, m.value());
    const auto r = m->result();
    if (r)
      out.noise = *r;
    else
      out.refused = r.error().message;
  }
  out.faults = bench.faults();
  out.simulated_s = bench.now();
  return out;
}

DriftSimResult simulate_drift_scan(const CalibrationSimSetup& setup,
                                   const CalibrationSource& source,
                                   const calibration::DriftSpec& spec) {
  SkyBench bench(setup);
  DriftSimResult out;
  const auto here = source.track(0.0);
  const auto later = source.track(60.0);
  if (here && later) out.rate_deg_s = calibration::separation_deg(*here, *later) / 60.0;
  auto started = calibration::DriftScan::start(spec, out.rate_deg_s, bench.now());
  const auto held = started ? source.track(started->transit_s()) : std::nullopt;
  if (!started || !held) {
    out.refused =
        started ? "the source's place at the transit is unknown" : started.error().message;
    return out;
  }
  calibration::DriftScan& drift = started.value();
  out.transit_s = drift.transit_s();
  out.held = *held;
  while (!drift.done()) {
    bench.hold(*held);
    drift.tick(bench.now(), bench.driving(), bench.encoders(), bench.source_from_beam(source));
    if (const auto r = bench.reading()) drift.reading(bench.now(), *r);
  }
  const auto fit = drift.fit();
  if (fit)
    out.fit = *fit;
  else
    out.refused = fit.error().message;
  out.faults = bench.faults();
  out.simulated_s = bench.now();
  return out;
}

}  // namespace azt::sim
