#include "cli/simulate_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "azt/sim/calibration_sim.hpp"
#include "calibration/fit_report.hpp"
#include "cli/simulated_sky.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

/// The simulated sky (simulated_sky.hpp, shared with the noise scenarios) with the session's
/// epoch and its Sun cadence.
std::unique_ptr<SimulatedSky> sky_for(const SimConfig& c, const CalibrationScenario& o) {
  auto sky = simulated_sky(c, o.from, o.hours);
  sky->setup.epoch = sky->start;
  sky->setup.sun_every_s = o.sun_every_min * 60.0;
  return sky;
}

nlohmann::json beam_error_json(const calibration::BeamError& e) {
  return {{"residual_rms_deg", e.rms_deg},
          {"residual_max_deg", e.max_deg},
          {"directions", e.directions}};
}

/// Where the controller had to point, relative to the source, for the beam to be on it: what a
/// scan should find, known here because the mount's errors are the simulation's.
std::optional<calibration::SkyOffset> true_offset(const SimConfig& c, const control::AzEl& sky) {
  const auto mount = calibration::mount_for_sky(sky, c.setup.plant.pointing_errors);
  if (!mount) return std::nullopt;
  const auto believed = calibration::corrected_reading(*mount, c.setup.station.corrections.model);
  return calibration::offset_between(sky, believed);
}

nlohmann::json scan_json(const SimConfig& c, const sim::ScanRecord& r,
                         const astro::UtcInstant& start) {
  nlohmann::json j{{"source", r.source},
                   {"time", astro::format_iso8601_utc(astro::utc_plus(start, r.t_s))},
                   {"az_deg", r.sky.az_deg},
                   {"el_deg", r.sky.el_deg},
                   {"scans", r.scans}};
  if (!r.fit) {
    j["refused"] = r.refused;
    return j;
  }
  j["xel_offset_deg"] = r.fit->peak.xel_deg;
  j["el_offset_deg"] = r.fit->peak.el_deg;
  j["xel_std_deg"] = r.fit->peak_std.xel_deg;
  j["el_std_deg"] = r.fit->peak_std.el_deg;
  j["width_xel_deg"] = r.fit->width_xel_deg;
  j["width_el_deg"] = r.fit->width_el_deg;
  j["peak_db"] = r.fit->peak_db;
  j["noise_db"] = r.fit->noise_db;
  // Each line's offset at its own moment (calibration_sim.hpp).
  const auto xel_truth = true_offset(c, r.sky_xel);
  const auto el_truth = true_offset(c, r.sky);
  if (xel_truth && el_truth) {
    j["true_xel_offset_deg"] = xel_truth->xel_deg;
    j["true_el_offset_deg"] = el_truth->el_deg;
  }
  return j;
}

double largest_difference(const calibration::PointingTerms& a,
                          const calibration::PointingTerms& b) {
  const auto va = a.as_array(), vb = b.as_array();
  double worst = 0.0;
  for (std::size_t i = 0; i < va.size(); ++i)
    worst = std::max(worst, std::fabs(va.at(i) - vb.at(i)));
  return worst;
}

double cpu_since(std::clock_t start) {
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

}  // namespace

int run_calibrate_scenario(const SimConfig& config, const CalibrationScenario& o) {
  const auto sky = sky_for(config, o);
  const std::clock_t cpu = std::clock();
  const sim::CalibrationSimSetup& setup = sky->setup;
  const sim::CalibrationSimResult r = sim::simulate_calibration(setup);
  nlohmann::json scans = nlohmann::json::array();
  for (const sim::ScanRecord& s : r.scans) scans.push_back(scan_json(config, s, sky->start));
  const calibration::PointingTerms& truth = config.setup.plant.pointing_errors;
  nlohmann::json j{
      {"scenario", "calibrate"},
      {"injected", terms_json(truth)},
      {"before", beam_error_json(r.before)},
      {"after", beam_error_json(r.after)},
      {"after_with_encoders", beam_error_json(r.after_with_encoders)},
      {"quantisation_floor_deg", r.quantisation_floor_deg},
      {"encoder_bits",
       {{"az", config.setup.plant.az.encoder_bits}, {"el", config.setup.plant.el.encoder_bits}}},
      {"plan", {{"sun_every_s", setup.sun_every_s}, {"min_snr_db", setup.min_snr_db}}},
      {"log_rows", r.log.size()},
      {"scans", scans},
      {"faults", r.faults},
      {"simulated_s", r.simulated_s},
      {"cpu_s", cpu_since(cpu)}};
  if (r.fit) {
    j["fitted"] = terms_json(r.fit->terms);
    j["std_errors"] = terms_json(r.fit->std_errors);
    j["largest_term_error_deg"] = largest_difference(r.fit->terms, truth);
    j["observation_rms_deg"] = {{"before", r.fit->rms_before_deg}, {"after", r.fit->rms_deg}};
    j["held"] = fit_json(*r.fit, r.log)["held"];
  } else {
    j["fit_refused"] = r.fit_refused;
  }
  std::cout << (o.json ? j.dump() : j.dump(2)) << '\n';
  return r.fit ? 0 : 1;
}

int run_scan_scenario(const SimConfig& config, const CalibrationScenario& o) {
  if (o.source.empty()) throw UsageError("scan needs --source (sun, moon or a radio source)");
  const auto sky = sky_for(config, o);
  const sim::CalibrationSimSetup& setup = sky->setup;
  const auto found =
      std::find_if(setup.sources.begin(), setup.sources.end(),
                   [&o](const sim::CalibrationSource& s) { return s.name == o.source; });
  if (found == setup.sources.end()) {
    throw UsageError("--source must be sun, moon or a catalogue source with a flux at the band");
  }
  const std::clock_t cpu = std::clock();
  const sim::ScanRecord r = sim::simulate_single_scan(setup, *found);
  nlohmann::json j{
      {"scenario", "scan"}, {"scan", scan_json(config, r, sky->start)}, {"cpu_s", cpu_since(cpu)}};
  if (r.fit) {
    // The offsets as the Offset screen takes them (mount degrees: what to add to the azimuth
    // and elevation), found and true, each at its line's moment.
    const auto az_offset = [](const control::AzEl& source, const control::AzEl& at) {
      return std::remainder(at.az_deg - source.az_deg, 360.0);
    };
    j["found"] = {
        {"az_offset_deg", az_offset(r.sky_xel, calibration::apply_offset(r.sky_xel, r.fit->peak))},
        {"el_offset_deg", calibration::apply_offset(r.sky, r.fit->peak).el_deg - r.sky.el_deg}};
    const calibration::PointingTerms& errors = config.setup.plant.pointing_errors;
    const auto mount_xel = calibration::mount_for_sky(r.sky_xel, errors);
    const auto mount_el = calibration::mount_for_sky(r.sky, errors);
    if (mount_xel && mount_el) {
      j["true"] = {{"az_offset_deg", az_offset(r.sky_xel, *mount_xel)},
                   {"el_offset_deg", mount_el->el_deg - r.sky.el_deg}};
    }
  }
  std::cout << (o.json ? j.dump() : j.dump(2)) << '\n';
  return r.fit ? 0 : 1;
}

}  // namespace azt::app
