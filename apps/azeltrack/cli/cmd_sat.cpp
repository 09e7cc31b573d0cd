// `azeltrack sat` and `azeltrack passes` (docs/satellites.md): a satellite from an element-set
// file, where it is now (or at --at) with its Doppler, and its passes over a horizon mask.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "azt/orbit/element_age.hpp"
#include "azt/orbit/link_doppler.hpp"
#include "cli/commands.hpp"
#include "common/horizon_mask_option.hpp"
#include "common/sky_setup.hpp"
#include "common/usage_error.hpp"
#include "satellites/satellite_catalogue.hpp"

namespace azt::app {
namespace {

struct SatOptions {
  std::string sat;
  std::string tle;
  std::string at;
  std::string lat, lon, alt = "0", grid;
  std::string dut1 = "0";
  std::string downlink_mhz, uplink_mhz;
  // passes
  std::string from, hours = "24", min_el = "0", mask;
  bool json = false;
};

struct Station {
  astro::Observer site;
  std::string grid;
  double dut1_s = 0.0;
};

Station station_from(const SatOptions& o) {
  Station s;
  s.site = observer_from_options(o.grid, o.lat, o.lon, o.alt, s.grid);
  s.dut1_s = parse_number_option("--dut1", o.dut1);
  check_dut1(s.dut1_s);
  return s;
}

astro::UtcInstant instant(const std::string& option, const std::string& text) {
  if (text.empty()) return utc_now();
  auto t = astro::parse_iso8601_utc(text);
  if (!t) throw UsageError(option + ": " + t.error().message);
  return *t;
}

std::optional<double> frequency(const std::string& option, const std::string& text) {
  if (text.empty()) return std::nullopt;
  const double f = parse_number_option(option, text);
  if (f <= 0.0 || f > 1e6) throw UsageError(option + " must be in (0, 1e6] MHz");
  return f;
}

/// The daemon's default limits ([satellites] stale_days, refuse_days; docs/satellites.md).
const orbit::ElementAgeLimits kAgeLimits{};

bool stale(const orbit::Satellite& sat, const astro::UtcInstant& utc) {
  return orbit::judge_element_age(element_age_days(sat.elements, utc), kAgeLimits) !=
         orbit::ElementAge::Fresh;
}

void warn_age(const orbit::Satellite& sat, const astro::UtcInstant& utc) {
  const double age = element_age_days(sat.elements, utc);
  if (const std::string refusal = orbit::element_age_refusal(sat.elements.label(), age, kAgeLimits);
      !refusal.empty()) {
    std::cerr << "azeltrack: warning: " << refusal << " (the daemon would not track it)\n";
  } else if (stale(sat, utc)) {
    std::cerr << "azeltrack: warning: the elements of " << sat.elements.label() << " are "
              << std::fixed << std::setprecision(1) << age
              << " days from their epoch: passes are stale; fetch fresh ones\n";
  }
}

int run_sat(const SatOptions& o) {
  if (o.tle.empty()) throw UsageError("sat: --tle FILE is required");
  const Station st = station_from(o);
  const SatelliteCatalogue cat = SatelliteCatalogue::load(o.tle);
  const orbit::Satellite& sat = cat.find(o.sat);
  const astro::UtcInstant utc = instant("--at", o.at);
  warn_age(sat, utc);
  auto l = look(sat, utc, st.dut1_s, st.site);
  if (!l) throw std::runtime_error(l.error().message);
  nlohmann::json j{{"sat", sat.elements.label()},
                   {"norad", sat.elements.catalog},
                   {"utc", astro::format_iso8601_utc(utc)},
                   {"observer",
                    {{"grid", st.grid},
                     {"lat_deg", st.site.lat_deg},
                     {"lon_deg", st.site.lon_deg},
                     {"alt_m", st.site.height_m}}},
                   {"az_deg", l->az_deg},
                   {"el_deg", l->el_deg},
                   {"range_km", l->range_km},
                   {"range_rate_km_s", l->range_rate_km_s},
                   {"element_age_days", element_age_days(sat.elements, utc)},
                   {"stale", stale(sat, utc)}};
  if (const auto f = frequency("--downlink-mhz", o.downlink_mhz)) {
    j["downlink_mhz"] = *f;
    j["downlink_hz"] = orbit::downlink_hz(*f * 1e6, l->range_rate_km_s);
    j["downlink_doppler_hz"] = j["downlink_hz"].get<double>() - *f * 1e6;
  }
  if (const auto f = frequency("--uplink-mhz", o.uplink_mhz)) {
    j["uplink_mhz"] = *f;
    j["uplink_hz"] = orbit::uplink_hz(*f * 1e6, l->range_rate_km_s);
    j["uplink_doppler_hz"] = j["uplink_hz"].get<double>() - *f * 1e6;
  }
  if (o.json) {
    std::cout << j.dump() << '\n';
    return 0;
  }
  std::cout << std::fixed << std::setprecision(3) << j["sat"].get<std::string>() << " ("
            << sat.elements.catalog << ") at " << j["utc"].get<std::string>() << " from " << st.grid
            << "\n  az " << l->az_deg << "°  el " << l->el_deg << "°  range " << l->range_km
            << " km  range rate " << std::setprecision(5) << l->range_rate_km_s << " km/s\n";
  for (const char* k : {"downlink", "uplink"}) {
    if (j.contains(std::string(k) + "_hz")) {
      std::cout << std::setprecision(1) << "  " << k << " "
                << j[std::string(k) + "_hz"].get<double>() << " Hz (" << std::showpos
                << j[std::string(k) + "_doppler_hz"].get<double>() << std::noshowpos << " Hz)\n";
    }
  }
  return 0;
}

int run_passes(const SatOptions& o) {
  if (o.tle.empty()) throw UsageError("passes: --tle FILE is required");
  const Station st = station_from(o);
  const double hours = parse_number_option("--hours", o.hours);
  if (hours <= 0.0 || hours > 24.0 * 31) throw UsageError("--hours must be in (0, 744]");
  const orbit::HorizonMask mask = o.mask.empty() ? parse_horizon_mask("--min-el", o.min_el)
                                                 : parse_horizon_mask("--mask", o.mask);
  const SatelliteCatalogue cat = SatelliteCatalogue::load(o.tle);
  const orbit::Satellite& sat = cat.find(o.sat);
  const astro::UtcInstant from = instant("--from", o.from);
  warn_age(sat, from);
  auto passes = find_satellite_passes(sat, from, hours, mask, st.dut1_s, st.site);
  if (!passes) throw std::runtime_error(passes.error().message);
  const auto iso = [&from](double t) { return astro::format_iso8601_utc(utc_plus(from, t)); };
  for (const orbit::Pass& p : passes.value()) {
    const nlohmann::json j{{"sat", sat.elements.label()},
                           {"aos", iso(p.aos_s)},
                           {"tca", iso(p.tca_s)},
                           {"los", iso(p.los_s)},
                           {"max_el_deg", p.max_el_deg},
                           {"aos_az_deg", p.aos_az_deg},
                           {"tca_az_deg", p.tca_az_deg},
                           {"los_az_deg", p.los_az_deg},
                           {"duration_s", p.los_s - p.aos_s},
                           {"starts_before_window", p.starts_before_window},
                           {"ends_after_window", p.ends_after_window},
                           {"stale", stale(sat, utc_plus(from, p.aos_s))}};
    if (o.json) {
      std::cout << j.dump() << '\n';
    } else {
      std::cout << std::fixed << std::setprecision(1) << j["aos"].get<std::string>() << "  AOS az "
                << std::setw(5) << p.aos_az_deg << "  TCA " << j["tca"].get<std::string>() << " el "
                << std::setw(4) << p.max_el_deg << "  LOS " << j["los"].get<std::string>() << " az "
                << std::setw(5) << p.los_az_deg << (j["stale"].get<bool>() ? "  (stale)" : "")
                << '\n';
    }
  }
  if (!o.json && passes.value().empty()) std::cout << "no passes\n";
  return 0;
}

void station_options(CLI::App* cmd, SatOptions& o) {
  cmd->add_option("--tle", o.tle, "Element sets: TLE (2- or 3-line) or OMM (XML, JSON, KVN, CSV)");
  cmd->add_option("--lat", o.lat, "Station latitude, degrees north (WGS84)");
  cmd->add_option("--lon", o.lon, "Station longitude, degrees east (WGS84)");
  cmd->add_option("--alt", o.alt, "Station height above the ellipsoid, metres (default 0)");
  cmd->add_option("--grid", o.grid, "Station Maidenhead locator, instead of --lat/--lon");
  cmd->add_option("--dut1", o.dut1, "UT1-UTC in seconds (default 0)");
  cmd->add_flag("--json", o.json, "JSON output");
}

}  // namespace

Runner add_sat_command(CLI::App& app) {
  auto opts = std::make_shared<SatOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sat", "Where a satellite is: az/el, range, range rate and Doppler (SGP4)");
  cmd->add_option("satellite", opts->sat,
                  "Name (case-insensitive, or a unique prefix) or NORAD number")
      ->required();
  station_options(cmd, *opts);
  cmd->add_option("--at", opts->at, "UTC instant, ISO 8601; default now");
  cmd->add_option("--downlink-mhz", opts->downlink_mhz, "Downlink frequency: what is heard");
  cmd->add_option("--uplink-mhz", opts->uplink_mhz, "Uplink frequency: what to transmit");
  return [opts] { return run_sat(*opts); };
}

Runner add_passes_command(CLI::App& app) {
  auto opts = std::make_shared<SatOptions>();
  CLI::App* cmd = app.add_subcommand("passes", "A satellite's passes: AOS, TCA, LOS");
  cmd->add_option("satellite", opts->sat,
                  "Name (case-insensitive, or a unique prefix) or NORAD number")
      ->required();
  station_options(cmd, *opts);
  cmd->add_option("--from", opts->from, "Start, UTC ISO 8601; default now");
  cmd->add_option("--hours", opts->hours, "Length of the search, hours (default 24)");
  cmd->add_option("--min-el", opts->min_el, "Flat horizon, degrees (default 0)");
  cmd->add_option("--mask", opts->mask,
                  "Horizon mask: AZ:MIN_EL sectors, e.g. 0:5,90:12,200:3 (instead of --min-el)");
  return [opts] { return run_passes(*opts); };
}

}  // namespace azt::app
