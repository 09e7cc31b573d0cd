// `azeltrack watch`: a live terminal view of the sky for the configured station, once a second,
// until Ctrl-C. The daemon (a later issue) replaces this as the main job.
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

#include "azt/astro/bands.hpp"
#include "cli/commands.hpp"
#include "common/sky_report.hpp"
#include "common/usage_error.hpp"
#include "config/sky_config.hpp"

namespace azt::app {
namespace {

volatile std::sig_atomic_t g_stop = 0;
extern "C" void on_signal(int /*signal*/) { g_stop = 1; }

struct WatchOptions {
  std::string config = "examples/station.toml";
  int count = 0;   // frames to draw, 0 = until interrupted
  std::string at;  // fixed instant (for tests and screenshots), default: the clock
};

std::string row(const astro::TargetReport& r) {
  const auto& p = r.observation.place;
  std::ostringstream out;
  out << std::left << std::setw(20) << r.target.name << std::right << std::fixed
      << std::setprecision(2) << std::setw(8) << p.az_deg << std::setw(8) << r.observation.el_deg
      << std::setw(8) << p.el_geometric_deg << std::setprecision(3) << std::setw(10) << p.ra_deg
      << std::setw(9) << p.dec_deg << (r.observation.el_deg > 0.0 ? "  up" : "");
  return out.str();
}

/// `moon` now and `moon_later` one minute on: the Doppler drift an operator retunes for.
std::string moon_lines(const astro::TargetReport& moon, const astro::TargetReport& moon_later,
                       const SkyConfig& c) {
  const auto& p = moon.observation.place;
  const double f = *c.settings.freq_mhz;
  const double drift_hz_min =
      astro::self_echo_doppler_hz(f, *moon_later.observation.place.range_rate_km_s) -
      astro::self_echo_doppler_hz(f, *p.range_rate_km_s);
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << "\nMoon  distance " << *p.distance_km
      << " km   echo delay " << std::setprecision(3) << astro::echo_delay_s(*p.distance_km)
      << " s   range rate " << std::setprecision(1) << *p.range_rate_km_s * 1000.0 << " m/s\n"
      << "Echo  " << c.band_name << " band (" << std::setprecision(3) << f
      << " MHz): " << std::showpos << std::setprecision(0)
      << astro::self_echo_doppler_hz(f, *p.range_rate_km_s) << " Hz (" << std::setprecision(1)
      << drift_hz_min << " Hz/min)" << std::noshowpos << std::setprecision(0);
  if (moon.dx_range_rate_km_s) {
    out << "   DX " << c.settings.dx_grid << ": " << std::showpos
        << astro::dx_echo_doppler_hz(f, *p.range_rate_km_s, *moon.dx_range_rate_km_s) << " Hz"
        << std::noshowpos << " (DX sees the Moon at el " << std::setprecision(1)
        << moon.dx_place->el_geometric_deg << "°)";
  }
  out << '\n';
  return out.str();
}

std::string frame(const astro::Ephemeris& eph, const SkyConfig& c, const astro::UtcInstant& utc) {
  const astro::SkySnapshot snapshot = sky_snapshot_or_throw(eph, c.settings, utc);
  std::ostringstream out;
  out << "azeltrack  " << astro::format_iso8601_utc(utc) << "  station " << c.settings.grid << " ("
      << std::fixed << std::setprecision(4) << c.settings.observer.lat_deg << ", "
      << c.settings.observer.lon_deg << ", " << std::setprecision(0) << c.settings.observer.height_m
      << " m)  ephemeris " << eph.name() << "  refraction "
      << astro::to_string(c.settings.atmosphere.model) << "\nTAI-UTC " << std::setprecision(0)
      << snapshot.time().tai_minus_utc_s << " s  DUT1 " << std::showpos << std::setprecision(3)
      << snapshot.time().dut1_s << std::noshowpos << " s  band " << c.band_name << "\n\n"
      << std::left << std::setw(20) << "target" << std::right << std::setw(8) << "az°"
      << std::setw(8) << "el°" << std::setw(8) << "geom°" << std::setw(10) << "RA°" << std::setw(9)
      << "Dec°" << '\n';
  std::optional<astro::TargetReport> moon;
  for (const auto& target : c.targets) {
    astro::TargetReport r = observe_or_throw(snapshot, target);
    out << row(r) << '\n';
    if (target.kind == astro::Target::Kind::Moon) moon = r;
  }
  if (moon) {
    const astro::UtcInstant later{astro::JulianDate{utc.jd.jd1, utc.jd.jd2 + 60.0 / 86400.0}};
    const astro::SkySnapshot next = sky_snapshot_or_throw(eph, c.settings, later);
    out << moon_lines(*moon, observe_or_throw(next, moon->target), c);
  }
  return out.str();
}

/// Sleeps until the next whole UTC second (or until interrupted), polling the stop flag.
void wait_for_next_second() {
  using clock = std::chrono::system_clock;
  const auto now = clock::now();
  const auto next = std::chrono::ceil<std::chrono::seconds>(now + std::chrono::milliseconds(1));
  while (g_stop == 0 && clock::now() < next) {
    std::this_thread::sleep_for(
        std::min<clock::duration>(next - clock::now(), std::chrono::milliseconds(100)));
  }
}

int run_watch(const WatchOptions& o) {
  const SkyConfig config = load_sky_config(o.config);
  const auto ephemeris = open_ephemeris(config.settings.ephemeris);
  std::optional<astro::UtcInstant> fixed;
  if (!o.at.empty()) {
    auto parsed = astro::parse_iso8601_utc(o.at);
    if (!parsed) throw UsageError("--at: " + parsed.error().message);
    fixed = *parsed;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  const bool tty = isatty(STDOUT_FILENO) != 0;
  for (int n = 0; g_stop == 0 && (o.count == 0 || n < o.count); ++n) {
    const std::string text = frame(*ephemeris, config, fixed ? *fixed : utc_now());
    std::cout << (tty ? "\x1b[H\x1b[2J" : "") << text << (tty ? "\nCtrl-C to quit\n" : "\n")
              << std::flush;
    if (o.count == 0 || n + 1 < o.count) wait_for_next_second();
  }
  return 0;
}

}  // namespace

Runner add_watch_command(CLI::App& app) {
  auto opts = std::make_shared<WatchOptions>();
  CLI::App* cmd =
      app.add_subcommand("watch", "Live terminal view of the sky for the configured station");
  cmd->add_option("--config", opts->config,
                  "Configuration file (TOML), default examples/station.toml");
  cmd->add_option("--count", opts->count, "Draw this many frames and exit (default: until Ctrl-C)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--at", opts->at, "Show a fixed UTC instant instead of the clock");
  return [opts] { return run_watch(*opts); };
}

}  // namespace azt::app
