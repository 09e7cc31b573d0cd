// `azeltrack moon-windows` (docs/eme.md): the common Moon windows of two stations, with the best
// minute's Dgrd, Tsky and Dpol and the Sun's separation, for planning a sked.

#include <iomanip>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "azt/astro/bands.hpp"
#include "azt/eme/moon_windows.hpp"
#include "cli/commands.hpp"
#include "common/horizon_mask_option.hpp"
#include "common/moon_window_report.hpp"
#include "common/sky_setup.hpp"
#include "config/config_schema.hpp"

namespace azt::app {
namespace {

struct MoonWindowOptions {
  std::string grid, lat, lon, alt = "0", dx_grid, from, days = "30", min_el = "0", dx_min_el = "0",
                              mask, dx_mask, band = "144", ephemeris = "auto", fixed_el,
                              beam_width = "20";
  bool json = false;
};

orbit::HorizonMask station_mask(const std::string& option, const std::string& mask,
                                const std::string& min_el_option, const std::string& min_el) {
  return mask.empty() ? parse_horizon_mask(min_el_option, min_el)
                      : parse_horizon_mask(option, mask);
}

/// `--fixed-el` / `--beam-width`: a number within the range of its [mount.el] key (the
/// configuration's own check and words).
double fixed_array_option(const std::string& flag, const std::string& text, std::string_view key) {
  const double value = parse_number_option(flag, text);
  const KeySpec* spec = find_key(*find_section("mount.el"), key);
  if (auto why = key_violation(*spec, toml::value<double>(value))) {
    throw UsageError(flag + " " + *why + " (as [mount.el] " + std::string(key) + ")");
  }
  return value;
}

eme::MoonWindowSettings settings_from(const MoonWindowOptions& o) {
  eme::MoonWindowSettings s;
  if (o.from.empty()) {
    s.from_unix_s = utc_now().unix_seconds();
  } else {
    const auto t = astro::parse_iso8601_utc(o.from);
    if (!t) throw UsageError("--from: " + t.error().message);
    s.from_unix_s = t->unix_seconds();
  }
  s.days = parse_number_option("--days", o.days);
  if (!(s.days > 0.0 && s.days <= 366.0)) throw UsageError("--days must be in (0, 366]");
  s.mask = station_mask("--mask", o.mask, "--min-el", o.min_el);
  s.dx_mask = station_mask("--dx-mask", o.dx_mask, "--dx-min-el", o.dx_min_el);
  const astro::AmateurBand* band = astro::find_band(o.band);
  if (band == nullptr) throw UsageError("--band: '" + o.band + "' is not a known band");
  s.freq_mhz = band->freq_mhz;
  if (o.fixed_el.empty()) return s;
  const double fixed_el = fixed_array_option("--fixed-el", o.fixed_el, "fixed_deg");
  const double beam = fixed_array_option("--beam-width", o.beam_width, "beam_width_deg");
  return eme::in_fixed_beam(s, fixed_el, beam);
}

void print_window(const nlohmann::json& j) {
  const double minutes = j["duration_s"].get<double>() / 60.0;
  std::cout << j["start"].get<std::string>().substr(0, 16) << " to "
            << j["end"].get<std::string>().substr(11, 5) << "  " << std::setw(3)
            << static_cast<int>(minutes / 60) << "h" << std::setw(2) << std::setfill('0')
            << static_cast<int>(minutes) % 60 << std::setfill(' ') << "  best "
            << j["best"].get<std::string>().substr(11, 5) << std::fixed << std::setprecision(1)
            << "  Dgrd " << std::setw(5) << j["dgrd_db"].get<double>() << " dB  Tsky "
            << std::setw(5) << std::setprecision(0) << j["tsky_k"].get<double>() << " K  Dpol "
            << std::setw(4) << j["dpol_deg"].get<double>() << "°  Sun " << std::setw(4)
            << j["sun_sep_deg"].get<double>() << "°\n";
}

int run_moon_windows(const MoonWindowOptions& o) {
  std::string grid;
  const astro::Observer own = observer_from_options(o.grid, o.lat, o.lon, o.alt, grid);
  if (o.dx_grid.empty()) throw UsageError("moon-windows: --dx-grid LOC is required");
  const astro::Observer dx = observer_from_grid(o.dx_grid, 0.0);
  const eme::MoonWindowSettings s = settings_from(o);
  const auto ephemeris = open_ephemeris(o.ephemeris);
  const auto windows = eme::moon_windows(*ephemeris, own, dx, s, leap_table());
  if (!windows) throw std::runtime_error(windows.error().message);
  if (o.json) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& w : windows.value()) all.push_back(moon_window_json(w));
    nlohmann::json out{{"grid", grid}, {"dx_grid", o.dx_grid}, {"band", o.band}, {"windows", all}};
    if (s.max_el_deg) out["el_band_deg"] = {s.min_el_deg, *s.max_el_deg};
    std::cout << out.dump() << '\n';
    return 0;
  }
  std::cout << "Common Moon windows, " << grid << " and " << o.dx_grid << ", " << o.band
            << " MHz (UTC; Dpol between the stations)";
  if (s.max_el_deg) {
    std::cout << std::fixed << std::setprecision(1) << ", own Moon elevation " << s.min_el_deg
              << "° to " << *s.max_el_deg << "° (the fixed array's beam)";
  }
  std::cout << ":\n";
  for (const auto& w : windows.value()) print_window(moon_window_json(w));
  if (windows.value().empty()) std::cout << "none\n";
  return 0;
}

}  // namespace

Runner add_moon_windows_command(CLI::App& app) {
  auto o = std::make_shared<MoonWindowOptions>();
  CLI::App* cmd = app.add_subcommand(
      "moon-windows", "When two stations both see the Moon: common windows for an EME sked");
  cmd->add_option("--grid", o->grid, "Own Maidenhead locator (or --lat/--lon)");
  cmd->add_option("--lat", o->lat, "Own latitude, degrees north");
  cmd->add_option("--lon", o->lon, "Own longitude, degrees east");
  cmd->add_option("--alt", o->alt, "Own height, metres (default 0)");
  cmd->add_option("--dx-grid", o->dx_grid, "The DX station's locator")->required();
  cmd->add_option("--from", o->from, "Start, UTC ISO 8601; default now");
  cmd->add_option("--days", o->days, "How many days (default 30)");
  cmd->add_option("--min-el", o->min_el, "Own lowest elevation, degrees (default 0)");
  cmd->add_option("--mask", o->mask, "Own horizon mask: AZ:MIN_EL sectors (instead of --min-el)");
  cmd->add_option("--dx-min-el", o->dx_min_el, "The DX station's lowest elevation (default 0)");
  cmd->add_option("--dx-mask", o->dx_mask, "The DX station's horizon mask");
  cmd->add_option("--fixed-el", o->fixed_el,
                  "A fixed-elevation array's angle: the Moon only within its vertical beam");
  cmd->add_option("--beam-width", o->beam_width,
                  "With --fixed-el: the vertical half-power beam width, degrees (default 20)");
  cmd->add_option("--band", o->band, "Band for Tsky and Dgrd, MHz (default 144)");
  cmd->add_option("--ephemeris", o->ephemeris, "auto (default), swiss or erfa");
  cmd->add_flag("--json", o->json, "JSON output");
  return [o] { return run_moon_windows(*o); };
}

}  // namespace azt::app
