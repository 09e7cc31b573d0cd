#include "cli/simulate_noise.hpp"

#include <cmath>
#include <ctime>
#include <iostream>

#include <nlohmann/json.hpp>

#include "azt/calibration/noise_expectation.hpp"
#include "azt/calibration/scan_fit.hpp"
#include "azt/sim/noise_sim.hpp"
#include "cli/simulated_sky.hpp"

namespace azt::app {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinElDeg = 5.0;  ///< a source lower than this is not measured

double cpu_since(std::clock_t start) {
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

std::string iso_at(const SimulatedSky& sky, double t_s) {
  return astro::format_iso8601_utc(astro::utc_plus(sky.start, t_s));
}

/// The source at the start, refused (with the JSON to print) when it is not up.
std::optional<json> below_horizon(const sim::CalibrationSource& s, const std::string& scenario) {
  const auto at = s.track(0.0);
  if (at && at->el_deg >= kMinElDeg) return std::nullopt;
  return json{{"scenario", scenario},
              {"source", s.name},
              {"refused", s.name + " is below " + std::to_string(static_cast<int>(kMinElDeg)) +
                              "° of elevation at the start"}};
}

/// A real dish of the simulated receiver's diameter and efficiency would keep this share of its
/// beam in the main lobe: (η·A/λ²)·Ω_main, Ω_main = π·W²/(4 ln 2) for a Gaussian main beam. The
/// simulated receiver keeps all of it (a Gaussian of beamwidth_deg fills with a disc by
/// θ²/(θ² + W²)), so the expected value from flux and dish reads lower by this share.
double main_beam_share(const SimConfig& c) {
  const sim::ReceiverSetup& rx = c.receiver.receiver;
  const double lambda_m = 299792458.0 / (static_cast<double>(c.receiver.flux_mhz) * 1e6);
  const double area_m2 = kPi * rx.dish_m * rx.dish_m / 4.0;
  const double w_rad = rx.beamwidth_deg * kPi / 180.0;
  return rx.efficiency * area_m2 / (lambda_m * lambda_m) * kPi * w_rad * w_rad /
         (4.0 * std::log(2.0));
}

/// What the core's formula expects of the source's flux, with the simulated dish and receiver.
json expected_json(const SimConfig& c, const SkyEmitter& e, const calibration::NoiseResult* r) {
  const sim::ReceiverSetup& rx = c.receiver.receiver;
  const calibration::NoiseStation station{static_cast<double>(c.receiver.flux_mhz), rx.dish_m,
                                          rx.efficiency, rx.tsys_k, rx.beamwidth_deg};
  const calibration::SourceShape shape =
      e.size_deg > 0.0 ? calibration::SourceShape::Gaussian : calibration::SourceShape::Point;
  const auto x = calibration::expected_noise(station, {e.flux_jy, shape, e.size_deg});
  if (!x) return {{"refused", x.error().message}};
  json j{{"flux_sfu", e.flux_jy / calibration::kJanskyPerSfu},
         {"size_factor", x->size_factor},
         {"antenna_k", x->antenna_k},
         {"y_db", x->y_db},
         {"main_beam_share", main_beam_share(c)}};
  if (r != nullptr) {
    j["g_over_t_db"] =
        calibration::g_over_t_db(r->y_db, e.flux_jy, station.freq_mhz, x->size_factor);
    j["implied_tsys_k"] = calibration::implied_tsys_k(r->y_db, x->antenna_k);
  }
  return j;
}

json noise_json(const calibration::NoiseResult& r) {
  return {{"y_factor_db", r.y_db},    {"std_error_db", r.std_error_db},
          {"pair_y_db", r.pair_y_db}, {"pairs", r.pair_y_db.size()},
          {"on_db", r.on_db},         {"off_db", r.off_db},
          {"missed", r.missed}};
}

/// Where the controller had to point, relative to the source at `sky`, for the beam to be on
/// it: what a scan or a drift should find, known here because the mount's errors are the
/// simulation's.
std::optional<calibration::SkyOffset> true_offset(const SimConfig& c, const control::AzEl& sky) {
  const auto mount = calibration::mount_for_sky(sky, c.setup.plant.pointing_errors);
  if (!mount) return std::nullopt;
  const auto believed = calibration::corrected_reading(*mount, c.setup.station.corrections.model);
  return calibration::offset_between(sky, believed);
}

json drift_json(const SimConfig& c, const SimulatedSky& sky, const sim::CalibrationSource& src,
                const calibration::DriftFit& f) {
  const double truth = c.receiver.receiver.beamwidth_deg;
  const double found = calibration::deconvolved_beamwidth_deg(f.width_deg, src.size_deg);
  json j{{"peak_time", iso_at(sky, f.peak_s)},
         {"width_s", f.width_s},
         {"width_deg", f.width_deg},
         {"beamwidth_deg", found},
         {"truth_beamwidth_deg", truth},
         {"beamwidth_error_pct", 100.0 * (found - truth) / truth},
         {"width_std_deg", f.width_std_deg},
         {"along_offset_deg", f.along_offset_deg},
         {"along_std_deg", f.along_std_deg},
         {"direction", {{"xel", f.direction.xel_deg}, {"el", f.direction.el_deg}}},
         {"cross_track_deg", f.cross_track_deg},
         {"peak_db", f.peak_db},
         {"noise_db", f.noise_db},
         {"bins", f.used}};
  const auto at = src.track(f.peak_s);
  const auto t = at ? true_offset(c, *at) : std::nullopt;
  if (!t) return j;
  calibration::DriftFit truth_fit = f;  // the same reading of the path, with the true offset
  truth_fit.along_offset_deg = t->xel_deg * f.direction.xel_deg + t->el_deg * f.direction.el_deg;
  j["true_along_offset_deg"] = truth_fit.along_offset_deg;
  // The azimuth, taking the elevation as right (drift_fit.hpp), found and true alike.
  if (const auto az = calibration::drift_az_offset_deg(f, at->el_deg)) {
    j["az_offset_deg"] = *az;
    j["true_az_offset_deg"] = *calibration::drift_az_offset_deg(truth_fit, at->el_deg);
  }
  return j;
}

}  // namespace

int run_noise_scenario(const SimConfig& config, const CalibrationScenario& o,
                       const std::string& source) {
  const auto sky = simulated_sky(config, o.from, o.hours);
  const std::size_t i = source_index(*sky, source);
  const sim::CalibrationSource& src = sky->setup.sources[i];
  const std::string scenario = source + "-noise";
  if (const auto refused = below_horizon(src, scenario)) {
    std::cout << (o.json ? refused->dump() : refused->dump(2)) << '\n';
    return 1;
  }
  calibration::NoisePlan plan;
  plan.beamwidth_deg = config.receiver.receiver.beamwidth_deg;
  const std::clock_t cpu = std::clock();
  const sim::NoiseSimResult r = sim::simulate_noise_measurement(sky->setup, src, plan);
  // The truth from the simulated receiver's own model: the rise with the beam on the source,
  // over a sky with nothing else in the beam.
  const double truth_db =
      sim::SimulatedReceiver(config.receiver.receiver).peak_rise_db({{}, src.peak_k, src.size_deg});
  json j{{"scenario", scenario},
         {"source", source},
         {"time", iso_at(*sky, 0.0)},
         {"az_deg", r.sky.az_deg},
         {"el_deg", r.sky.el_deg},
         {"truth_db", truth_db},
         {"plan",
          {{"beamwidth_deg", plan.beamwidth_deg},
           {"offset_beams", plan.offset_beams},
           {"repeats", plan.repeats}}},
         {"expected", expected_json(config, sky->emitters[i], r.noise ? &*r.noise : nullptr)},
         {"faults", r.faults},
         {"simulated_s", r.simulated_s},
         {"cpu_s", cpu_since(cpu)}};
  if (r.peak) {
    j["peak"] = {{"xel_offset_deg", r.peak->peak.xel_deg}, {"el_offset_deg", r.peak->peak.el_deg}};
  } else {
    j["peak_refused"] = r.peak_refused;
  }
  if (r.noise) {
    j.update(noise_json(*r.noise));
    j["difference_db"] = r.noise->y_db - truth_db;
  } else {
    j["refused"] = r.refused;
  }
  std::cout << (o.json ? j.dump() : j.dump(2)) << '\n';
  return r.noise ? 0 : 1;
}

int run_drift_scenario(const SimConfig& config, const CalibrationScenario& o) {
  const std::string source = o.source.empty() ? "sun" : o.source;
  const auto sky = simulated_sky(config, o.from, o.hours);
  const sim::CalibrationSource& src = sky->setup.sources[source_index(*sky, source)];
  if (const auto refused = below_horizon(src, "drift")) {
    std::cout << (o.json ? refused->dump() : refused->dump(2)) << '\n';
    return 1;
  }
  calibration::DriftSpec spec;
  spec.beamwidth_deg = config.receiver.receiver.beamwidth_deg;
  const std::clock_t cpu = std::clock();
  const sim::DriftSimResult r = sim::simulate_drift_scan(sky->setup, src, spec);
  json j{{"scenario", "drift"},
         {"source", source},
         {"time", iso_at(*sky, 0.0)},
         {"transit", iso_at(*sky, r.transit_s)},
         {"held", {{"az_deg", r.held.az_deg}, {"el_deg", r.held.el_deg}}},
         {"rate_deg_s", r.rate_deg_s},
         {"faults", r.faults},
         {"simulated_s", r.simulated_s},
         {"cpu_s", cpu_since(cpu)}};
  if (r.fit) {
    j.update(drift_json(config, *sky, src, *r.fit));
  } else {
    j["refused"] = r.refused;
  }
  std::cout << (o.json ? j.dump() : j.dump(2)) << '\n';
  return r.fit ? 0 : 1;
}

}  // namespace azt::app
