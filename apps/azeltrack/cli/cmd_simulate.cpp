// `azeltrack simulate`: the real controller against the simulated antenna in virtual time.
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "antenna/sim_hub.hpp"
#include "azt/sim/pass_sim.hpp"
#include "azt/sim/pol_track.hpp"
#include "azt/sim/sky_track.hpp"
#include "azt/sim/station_sim.hpp"
#include "azt/track/satellite_pass_track.hpp"
#include "cli/commands.hpp"
#include "cli/simulate_calibration.hpp"
#include "cli/simulate_noise.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/sim_config.hpp"
#include "satellites/satellite_catalogue.hpp"

namespace azt::app {
namespace {

struct SimulateOptions {
  std::string config = "examples/sim.toml";
  std::string scenario;
  std::string from;
  std::string hours = "6";
  std::string to_az, to_el;
  std::string tle, sat;
  std::string source;
  std::string sun_every_min = "0";
  std::string ptt_period_s = "0";
  bool json = false;
};

nlohmann::json axis_json(const sim::AxisMetrics& m) {
  return {{"rms_error_deg", m.rms_error_deg},
          {"max_error_deg", m.max_error_deg},
          {"starts", m.starts},
          {"starts_per_hour", m.starts_per_hour},
          {"overshoot_deg", m.overshoot_deg},
          {"travel_deg", m.travel_deg}};
}

nlohmann::json result_json(const sim::SimResult& r, const std::string& scenario, double cpu_s,
                           const std::string& hub_kind) {
  auto opt = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  return {{"scenario", scenario},
          {"rms_error_deg", r.rms_error_deg},
          {"max_error_deg", r.max_error_deg},
          {"motor_starts_per_hour", {{"az", r.az.starts_per_hour}, {"el", r.el.starts_per_hour}}},
          {"slew_time_s", opt(r.slew_time_s)},
          {"slew_min_time_s", r.slew_min_time_s},
          {"overshoot_deg", std::max(r.az.overshoot_deg, r.el.overshoot_deg)},
          {"faults", r.faults},
          {"acquired_s", opt(r.acquired_s)},
          {"simulated_s", r.simulated_s},
          {"cpu_s", cpu_s},
          {"az", axis_json(r.az)},
          {"el", axis_json(r.el)},
          {"hub",
           {{"kind", hub_kind}, {"frames_ok", r.hub.frames_ok()}, {"rejected", r.hub.rejected()}}}};
}

/// With a pol axis: its error against the feed angle, beside az and el's.
void add_pol_json(nlohmann::json& j, const sim::SimResult& r, const SimConfig& c, double settle_s) {
  if (!r.pol) return;
  j["pol_max_error_deg"] = r.pol->max_error_deg;
  j["pol_rms_error_deg"] = r.pol->rms_error_deg;
  j["pol"] = axis_json(*r.pol);
  j["pol"]["mode"] = control::to_string(c.pol.mode);
  j["pol"]["settle_s"] = settle_s;
  j["pol"]["settling_s"] = r.pol_settling_s;
  j["pol"]["counted_s"] = r.pol_counted_s;
}

/// How long after a jump of the pol target its error is left uncounted: the turn between the
/// receive and transmit angles (Split: 2·dx_offset, folded) at the mount's rate, the soft start
/// and stop, and 2 s of final approach; 0 without a PTT sequence.
double pol_settle_s(const SimConfig& c, double ptt_period_s) {
  if (ptt_period_s <= 0.0 || !c.mount.pol || c.pol.mode != control::PolMode::Split) return 0.0;
  const double swing_deg = std::fabs(control::fold_linear_deg(2.0 * c.pol.dx_offset_deg));
  return swing_deg / c.mount.pol->axis.max_rate_deg_s + c.setup.station.pol->control.ramp_s + 2.0;
}

/// What the pol axis follows through the run: [pol] with Dpol to [sky] dx_grid and the PTT
/// sequence; an empty track without a pol axis.
sim::PolTracking pol_tracking(const SimConfig& c, const astro::Ephemeris& ephemeris,
                              const astro::UtcInstant& start, double ptt_period_s) {
  if (!c.setup.plant.pol || !c.setup.station.pol) return {};
  sim::PolTrackSetup p;
  p.ephemeris = &ephemeris;
  p.own = c.sky.settings.observer;
  p.dx = c.sky.settings.dx;
  p.start = start;
  p.dut1_s = c.sky.settings.dut1_s;
  p.leap_table = &leap_table();
  p.settings = c.pol;
  p.ptt_period_s = ptt_period_s;
  return sim::PolTracking{sim::make_pol_track(p), {}, pol_settle_s(c, ptt_period_s)};
}

sim::SimResult run_tracking(const SimConfig& c, const SimulateOptions& o, double hours,
                            double ptt_period_s) {
  const auto ephemeris = open_ephemeris(c.sky.settings.ephemeris);
  astro::UtcInstant start = utc_now();
  if (!o.from.empty()) {
    auto parsed = astro::parse_iso8601_utc(o.from);
    if (!parsed) throw UsageError("--from: " + parsed.error().message);
    start = *parsed;
  }
  time_scales_at(start, c.sky.settings.dut1_s);  // validates the instant, warns once if needed
  sim::SkyTrackSetup track;
  track.ephemeris = ephemeris.get();
  track.target = o.scenario == "sun" ? astro::Target::sun() : astro::Target::moon();
  track.observer = c.sky.settings.observer;
  track.atmosphere = c.sky.settings.atmosphere;
  track.start = start;
  track.dut1_s = c.sky.settings.dut1_s;
  track.leap_table = &leap_table();
  return sim::simulate_tracking(c.setup, sim::make_sky_track(track), hours * 3600.0,
                                make_sim_hub(c.setup.plant, c.hub),
                                pol_tracking(c, *ephemeris, start, ptt_period_s));
}

/// The next pass of --sat after --from, flown by the real controller on the simulated plant
/// (docs/satellites.md): the mount is the configuration's travel and plant rates.
int run_pass(const SimConfig& c, const SimulateOptions& o) {
  if (o.tle.empty() || o.sat.empty()) throw UsageError("pass needs --tle FILE and --sat NAME");
  const SatelliteCatalogue cat = SatelliteCatalogue::load(o.tle);
  const orbit::Satellite& sat = cat.find(o.sat);
  astro::UtcInstant from = utc_now();
  if (!o.from.empty()) {
    auto parsed = astro::parse_iso8601_utc(o.from);
    if (!parsed) throw UsageError("--from: " + parsed.error().message);
    from = *parsed;
  }
  const double dut1 = c.sky.settings.dut1_s;
  const astro::Observer& site = c.sky.settings.observer;
  auto passes = find_satellite_passes(sat, from, 48.0, orbit::HorizonMask::flat(0.0), dut1, site);
  if (!passes) throw std::runtime_error(passes.error().message);
  const orbit::Pass* next = nullptr;
  for (const auto& p : passes.value()) {
    if (!p.starts_before_window && !p.ends_after_window) {
      next = &p;
      break;
    }
  }
  if (next == nullptr)
    throw std::runtime_error("no whole pass of " + sat.elements.label() + " in 48 h");
  auto sky = track::sample_pass(sat, from, *next, dut1, site);
  if (!sky) throw std::runtime_error(sky.error().message);
  const track::MountGeometry mount = sim::mount_geometry(c.setup);
  const double prep_s = std::min(600.0, next->aos_s);
  const std::clock_t cpu_start = std::clock();
  auto r = sim::simulate_pass(sky.value(), mount, c.setup,
                              {c.setup.plant.az.start_deg, c.setup.plant.el.start_deg}, prep_s);
  if (!r) throw std::runtime_error(r.error().message);
  const double cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const auto iso = [&from](double t) { return astro::format_iso8601_utc(utc_plus(from, t)); };
  const nlohmann::json j{{"scenario", "pass"},
                         {"sat", sat.elements.label()},
                         {"aos", iso(next->aos_s)},
                         {"tca", iso(next->tca_s)},
                         {"los", iso(next->los_s)},
                         {"max_el_deg", next->max_el_deg},
                         {"flip", r->flip},
                         {"max_error_deg", r->max_error_deg},
                         {"rms_error_deg", r->rms_error_deg},
                         {"max_error_beyond_plan_deg", r->max_excess_deg},
                         {"planned_max_error_deg", r->planned_max_error_deg},
                         {"planned_loss_s", r->planned_loss_s},
                         {"loss_s", r->loss_s},
                         {"az_travel_deg", r->az_travel_deg},
                         {"pass_span_deg", r->pass_span_deg},
                         {"unwinds", r->unwinds},
                         {"faults", r->faults},
                         {"prepositioning_s", prep_s},
                         {"cpu_s", cpu_s}};
  std::cout << (o.json ? j.dump() : j.dump(2)) << '\n';
  return 0;
}

int run_simulate(const SimulateOptions& o) {
  if (o.scenario != "moon" && o.scenario != "sun" && o.scenario != "slew" && o.scenario != "pass" &&
      o.scenario != "calibrate" && o.scenario != "scan" && o.scenario != "sun-noise" &&
      o.scenario != "moon-noise" && o.scenario != "drift") {
    throw UsageError(
        "--scenario must be moon, sun, slew, pass, calibrate, scan, sun-noise, moon-noise or "
        "drift");
  }
  const SimConfig config = sim_config_from(ConfigFile::load(o.config));
  if (o.scenario == "pass") return run_pass(config, o);
  const double hours = parse_number_option("--hours", o.hours);
  if (hours <= 0.0 || hours > 48.0) throw UsageError("--hours must be in (0, 48]");
  const double sun_every_min = parse_number_option("--sun-every-min", o.sun_every_min);
  if (sun_every_min < 0.0 || sun_every_min > 1440.0) {
    throw UsageError("--sun-every-min must be in [0, 1440]");
  }
  const double ptt_period_s = parse_number_option("--ptt-period-s", o.ptt_period_s);
  if (ptt_period_s < 0.0 || ptt_period_s > 3600.0) {
    throw UsageError("--ptt-period-s must be in [0, 3600]");
  }
  const CalibrationScenario c{o.from, hours, o.source, sun_every_min, o.json};
  if (o.scenario == "calibrate" || o.scenario == "scan") {
    return o.scenario == "scan" ? run_scan_scenario(config, c) : run_calibrate_scenario(config, c);
  }
  if (o.scenario == "sun-noise") return run_noise_scenario(config, c, "sun");
  if (o.scenario == "moon-noise") return run_noise_scenario(config, c, "moon");
  if (o.scenario == "drift") return run_drift_scenario(config, c);
  const std::clock_t cpu_start = std::clock();
  sim::SimResult result;
  if (o.scenario == "slew") {
    if (o.to_az.empty() || o.to_el.empty()) throw UsageError("slew needs --to-az and --to-el");
    const control::AzEl to{parse_number_option("--to-az", o.to_az),
                           parse_number_option("--to-el", o.to_el)};
    if (to.az_deg < 0.0 || to.az_deg >= 360.0 ||
        !control::plan_elevation(to.el_deg, config.setup.station.el_range)) {
      throw UsageError("--to-az must be 0..360 and --to-el inside the elevation range");
    }
    result =
        sim::simulate_slew(config.setup, to, 3600.0, make_sim_hub(config.setup.plant, config.hub));
  } else {
    result = run_tracking(config, o, hours, ptt_period_s);
  }
  const double cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  nlohmann::json j =
      result_json(result, o.scenario, cpu_s, config.hub.firmware ? "firmware" : "model");
  add_pol_json(j, result, config, pol_settle_s(config, ptt_period_s));
  // [sim.az|el] brake: whether the controller's brake_release_s left the motor pulling against it.
  const auto& brakes = config.setup.plant.brakes;
  if (brakes[0] || brakes[1]) {
    j["brake_pulled_against_s"] = {{"az", result.brake_pulled_against_s[0]},
                                   {"el", result.brake_pulled_against_s[1]}};
  }
  // A fixed elevation is not tracked: no error of its own, only the angle it stands at.
  if (config.setup.station.el_fixed_deg)
    j["el"] = {{"fixed_deg", *config.setup.station.el_fixed_deg}};
  std::cout << (o.json ? j.dump() : j.dump(2)) << '\n';
  return 0;
}

}  // namespace

Runner add_simulate_command(CLI::App& app) {
  auto opts = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Run the real controller against the simulated antenna in virtual time");
  cmd->add_option("--config", opts->config, "Configuration file (default examples/sim.toml)");
  cmd->add_option("--scenario", opts->scenario,
                  "moon, sun, slew, pass, calibrate, scan, sun-noise, moon-noise or drift")
      ->required();
  cmd->add_option("--from", opts->from, "Start instant, ISO 8601 UTC (default now)");
  cmd->add_option("--hours", opts->hours, "Tracking duration in simulated hours (default 6)");
  cmd->add_option("--to-az", opts->to_az, "Slew target azimuth, degrees");
  cmd->add_option("--to-el", opts->to_el, "Slew target elevation, degrees");
  cmd->add_option("--tle", opts->tle, "pass: the element sets (TLE or OMM)");
  cmd->add_option("--sat", opts->sat, "pass: the satellite, by name or NORAD number");
  cmd->add_option("--source", opts->source,
                  "scan, drift: the source (sun, moon, a radio source; drift: default sun)");
  cmd->add_option("--sun-every-min", opts->sun_every_min,
                  "calibrate: scan the Sun every N minutes while it is up (default 0: when it "
                  "adds coverage, as the other sources)");
  cmd->add_option("--ptt-period-s", opts->ptt_period_s,
                  "moon, sun: with [mount.pol], transmit every other period of this length, "
                  "receiving first (default 0: never); the split mode turns the feed for each");
  cmd->add_flag("--json", opts->json, "One JSON line instead of indented JSON");
  return [opts] { return run_simulate(*opts); };
}

}  // namespace azt::app
