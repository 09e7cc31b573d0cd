#include <iomanip>
#include <iostream>
#include <memory>

#include "azt/astro/catalogue.hpp"
#include "azt/astro/target.hpp"
#include "azt/util/parse_number.hpp"
#include "cli/commands.hpp"
#include "common/sky_report.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

struct SkyOptions {
  std::string target;
  std::string at;
  std::string lat, lon, alt = "0", grid;
  std::string freq_mhz, dx_grid, dut1 = "0";
  std::string ephemeris = "auto";
  std::string pressure = "1013.25", temperature = "10", humidity = "0.5", refraction = "radio";
  bool json = false;
  bool list = false;
};

void print_catalogue(bool json) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : astro::radio_sources()) {
    auto flux = [](const std::optional<double>& v) {
      return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    };
    out.push_back({{"key", s.key},
                   {"name", s.name},
                   {"aliases", s.aliases},
                   {"ra_deg", s.ra_deg},
                   {"dec_deg", s.dec_deg},
                   {"kind", s.kind},
                   {"position_ref", s.position_ref},
                   {"flux_1296_jy", flux(s.flux_1296_jy)},
                   {"flux_2304_jy", flux(s.flux_2304_jy)},
                   {"flux_10368_jy", flux(s.flux_10368_jy)},
                   {"flux_ref", s.flux_ref}});
  }
  if (json) {
    std::cout << out.dump(2) << '\n';
    return;
  }
  std::cout << "sun, moon, radec:RA_DEG,DEC_DEG, and:\n";
  for (const auto& s : astro::radio_sources()) {
    std::cout << std::left << std::setw(7) << s.key << std::setw(20) << s.name << std::right
              << std::fixed << std::setprecision(4) << std::setw(10) << s.ra_deg << std::setw(10)
              << s.dec_deg << "  " << s.aliases << '\n';
  }
}

SkySettings settings_from(const SkyOptions& o) {
  SkySettings s;
  s.observer = observer_from_options(o.grid, o.lat, o.lon, o.alt, s.grid);
  if (!o.dx_grid.empty()) {
    s.dx = observer_from_grid(o.dx_grid, 0.0);
    s.dx_grid = o.dx_grid;
  }
  s.dut1_s = parse_number_option("--dut1", o.dut1);
  check_dut1(s.dut1_s);
  if (!o.freq_mhz.empty()) {
    const double f = parse_number_option("--freq-mhz", o.freq_mhz);
    if (f <= 0.0 || f > 1e6) throw UsageError("--freq-mhz must be in (0, 1e6] MHz");
    s.freq_mhz = f;
  }
  auto model = astro::parse_refraction_model(o.refraction);
  if (!model) throw UsageError("--refraction: " + model.error().message);
  auto atm = astro::Atmosphere::make(parse_number_option("--pressure-hpa", o.pressure),
                                     parse_number_option("--temperature-c", o.temperature),
                                     parse_number_option("--humidity", o.humidity), *model);
  if (!atm) throw UsageError(atm.error().message);
  s.atmosphere = *atm;
  s.ephemeris = o.ephemeris;
  return s;
}

/// Self-echo Doppler on every band, four bands to a line.
void print_band_table(const nlohmann::json& bands) {
  std::cout << "  self-echo Doppler by band (MHz: Hz):";
  int n = 0;
  for (const auto& b : bands) {
    std::cout << (n++ % 4 == 0 ? "\n   " : "") << std::setw(7) << b["band"].get<std::string>()
              << ": " << std::showpos << std::fixed << std::setprecision(0) << std::setw(7)
              << b["echo_doppler_hz"].get<double>() << std::noshowpos;
  }
  std::cout << '\n';
}

/// The Moon's EME conditions, as WSJT-X's Astronomical Data window names them.
void print_eme(const nlohmann::json& j) {
  std::cout << std::setprecision(1) << "  Sun separation " << j["sun_sep_deg"].get<double>()
            << "°, illuminated " << std::setprecision(0) << 100.0 * j["illumination"].get<double>()
            << " %, parallactic angle " << std::setprecision(1)
            << j["parallactic_deg"].get<double>() << "°\n";
  if (!j["tsky_k"].is_null()) {
    std::cout << "  Tsky " << std::setprecision(0) << j["tsky_k"].get<double>() << " K, Dgrd "
              << std::setprecision(1) << j["dgrd_db"].get<double>() << " dB at "
              << j["freq_mhz"].get<double>() << " MHz\n";
  }
  if (!j["width_hz"].is_null()) {
    std::cout << std::setprecision(1) << "  echo width " << j["width_hz"].get<double>() << " Hz";
    if (!j["dx_width_hz"].is_null())
      std::cout << ", DX " << j["dx_width_hz"].get<double>() << " Hz";
    std::cout << '\n';
  }
  if (!j["dx_dpol_deg"].is_null()) {
    std::cout << std::setprecision(1) << "  Dpol to DX " << std::showpos
              << j["dx_dpol_deg"].get<double>() << std::noshowpos << "°, MNR "
              << j["mnr_db"].get<double>() << " dB\n";
  }
}

void print_text(const nlohmann::json& j) {
  std::cout << std::fixed << std::setprecision(4) << j["target"].get<std::string>() << " at "
            << j["utc"].get<std::string>() << " from " << j["observer"]["grid"].get<std::string>()
            << " (" << j["ephemeris"].get<std::string>() << ")\n"
            << "  az " << j["az_deg"].get<double>() << "°  el " << j["el_deg"].get<double>()
            << "° (geometric " << j["el_geometric_deg"].get<double>() << "°, "
            << j["refraction"].get<std::string>() << " refraction)\n"
            << "  RA " << j["ra_deg"].get<double>() << "°  Dec " << j["dec_deg"].get<double>()
            << "° (apparent, topocentric)\n";
  if (!j["distance_km"].is_null()) {
    std::cout << std::setprecision(3) << "  distance " << j["distance_km"].get<double>()
              << " km, range rate " << std::setprecision(6) << j["range_rate_km_s"].get<double>()
              << " km/s\n";
  }
  if (j.contains("echo_delay_s")) {
    std::cout << std::setprecision(4) << "  echo delay " << j["echo_delay_s"].get<double>()
              << " s\n";
  }
  if (j.contains("echo_doppler_hz")) {
    std::cout << std::setprecision(1) << "  echo Doppler at " << j["freq_mhz"].get<double>()
              << " MHz: " << std::showpos << j["echo_doppler_hz"].get<double>() << std::noshowpos
              << " Hz\n";
  }
  if (j.contains("bands")) print_band_table(j["bands"]);
  if (j.contains("dx_echo_doppler_hz")) {
    std::cout << std::setprecision(1) << "  DX echo Doppler (" << j["dx"]["grid"].get<std::string>()
              << "): " << std::showpos << j["dx_echo_doppler_hz"].get<double>() << std::noshowpos
              << " Hz\n";
  }
  if (j.contains("sun_sep_deg")) print_eme(j);
}

int run_sky(const SkyOptions& o) {
  if (o.list) {
    print_catalogue(o.json);
    return 0;
  }
  if (o.target.empty()) throw UsageError("sky: TARGET is required (or --list)");
  auto target = astro::parse_target(o.target);
  if (!target) throw UsageError(target.error().message);
  const SkySettings settings = settings_from(o);
  astro::UtcInstant utc = utc_now();
  if (!o.at.empty()) {
    auto parsed = astro::parse_iso8601_utc(o.at);
    if (!parsed) throw UsageError("--at: " + parsed.error().message);
    utc = *parsed;
  }
  const auto ephemeris = open_ephemeris(settings.ephemeris);
  const astro::SkySnapshot snapshot = sky_snapshot_or_throw(*ephemeris, settings, utc);
  const nlohmann::json j =
      report_json(observe_or_throw(snapshot, *target), snapshot, settings, ephemeris->name());
  if (o.json) {
    std::cout << j.dump() << '\n';
  } else {
    print_text(j);
  }
  return 0;
}

}  // namespace

Runner add_sky_command(CLI::App& app) {
  auto opts = std::make_shared<SkyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sky", "Where a target is: az/el, RA/Dec, distance, range rate, Moon echo Doppler");
  cmd->add_option("target", opts->target,
                  "sun, moon, a catalogue name (see --list) or radec:RA_DEG,DEC_DEG");
  cmd->add_flag("--list", opts->list, "List the radio-source catalogue");
  cmd->add_option("--at", opts->at, "UTC instant, ISO 8601 (2025-03-14T06:00:00Z); default now");
  cmd->add_option("--lat", opts->lat, "Station latitude, degrees north (WGS84)");
  cmd->add_option("--lon", opts->lon, "Station longitude, degrees east (WGS84)");
  cmd->add_option("--alt", opts->alt, "Station height above the ellipsoid, metres (default 0)");
  cmd->add_option("--grid", opts->grid,
                  "Station Maidenhead locator (4-10 characters), instead of --lat/--lon");
  cmd->add_option("--freq-mhz", opts->freq_mhz, "Frequency for the Moon echo Doppler, MHz");
  cmd->add_option("--dx-grid", opts->dx_grid, "Locator of a DX station for the DX echo Doppler");
  cmd->add_option("--dut1", opts->dut1,
                  "UT1-UTC in seconds (default 0; beyond ±0.9 s warns, ±10 s max)");
  cmd->add_option("--ephemeris", opts->ephemeris, "auto (default), swiss or erfa");
  cmd->add_option("--refraction", opts->refraction, "radio (default), optical or none");
  cmd->add_option("--pressure-hpa", opts->pressure, "Station pressure, hPa (default 1013.25)");
  cmd->add_option("--temperature-c", opts->temperature, "Air temperature, °C (default 10)");
  cmd->add_option("--humidity", opts->humidity, "Relative humidity 0..1 (default 0.5)");
  cmd->add_flag("--json", opts->json, "Print one JSON object");
  return [opts] { return run_sky(*opts); };
}

}  // namespace azt::app
