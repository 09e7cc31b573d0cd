// azeltrack: one executable, subcommands (CLI11). Exit codes: 0 success, 1 failure, 2 bad usage.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "cli/commands.hpp"
#include "common/program_version.hpp"
#include "common/usage_error.hpp"

namespace {

void setup_logging() {
  // Diagnostics go to stderr so that --json output on stdout stays machine-readable.
  auto logger = spdlog::stderr_color_mt("azeltrack");
  logger->set_pattern("azeltrack: %l: %v");
  spdlog::set_default_logger(logger);
}

}  // namespace

int main(int argc, char** argv) {
  setup_logging();
  CLI::App app{"azeltrack: antenna tracking controller for EME, satellites and radio astronomy"};
  app.set_version_flag("--version", "azeltrack " + std::string(azt::app::program_version()));
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  azeltrack sky moon --grid FN06HE --freq-mhz 10368      where the Moon is, echo Doppler\n"
      "  azeltrack sky casa --lat 46.189 --lon -79.393 --json   Cassiopeia A as JSON\n"
      "  azeltrack sky --list                                   the radio-source catalogue\n"
      "  azeltrack locator FN06HE                               centre of a locator square\n"
      "  azeltrack moon-windows --grid FN06HE --dx-grid JO62    common Moon windows for a sked\n"
      "  azeltrack watch --config examples/station.toml         live sky view (scripts/run)\n"
      "  azeltrack simulate --scenario moon --hours 6           the controller on the sim antenna\n"
      "  azeltrack serve --config examples/sim.toml            the daemon (scripts/run)\n"
      "  azeltrack config set --config my.toml control.window_deg 0.2   validated, atomic\n"
      "  azeltrack hub encode --az-bits 12 --el-bits 12 --az-raw 2048 --el-raw 100\n"
      "  azeltrack pointing fit --csv scans.csv --json          the pointing model from scans\n"
      "Exit codes: 0 success, 1 failure, 2 bad arguments.");
  const azt::app::Runner sky = azt::app::add_sky_command(app);
  const azt::app::Runner locator = azt::app::add_locator_command(app);
  const azt::app::Runner watch = azt::app::add_watch_command(app);
  const azt::app::Runner simulate = azt::app::add_simulate_command(app);
  const azt::app::Runner hub = azt::app::add_hub_command(app);
  const azt::app::Runner serve = azt::app::add_serve_command(app);
  const azt::app::Runner config = azt::app::add_config_command(app);
  const azt::app::Runner web = azt::app::add_web_command(app);
  const azt::app::Runner seq_sim = azt::app::add_seq_sim_command(app);
  const azt::app::Runner sat = azt::app::add_sat_command(app);
  const azt::app::Runner passes = azt::app::add_passes_command(app);
  const azt::app::Runner moon_windows = azt::app::add_moon_windows_command(app);
  const azt::app::Runner schedule = azt::app::add_schedule_command(app);
  const azt::app::Runner pointing = azt::app::add_pointing_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, exit 2, whatever CLI11's own code would be.
    azt::app::print_error(std::string(e.what()) + " (see azeltrack --help)");
    return azt::app::kExitUsage;
  }
  try {
    if (app.got_subcommand("sky")) return sky();
    if (app.got_subcommand("locator")) return locator();
    if (app.got_subcommand("watch")) return watch();
    if (app.got_subcommand("simulate")) return simulate();
    if (app.got_subcommand("hub")) return hub();
    if (app.got_subcommand("serve")) return serve();
    if (app.got_subcommand("config")) return config();
    if (app.got_subcommand("web")) return web();
    if (app.got_subcommand("seq-sim")) return seq_sim();
    if (app.got_subcommand("sat")) return sat();
    if (app.got_subcommand("passes")) return passes();
    if (app.got_subcommand("moon-windows")) return moon_windows();
    if (app.got_subcommand("schedule")) return schedule();
    if (app.got_subcommand("pointing")) return pointing();
  } catch (const azt::app::UsageError& e) {
    azt::app::print_error(e.what());
    return azt::app::kExitUsage;
  } catch (const std::exception& e) {
    azt::app::print_error(e.what());
    return azt::app::kExitFailure;
  }
  return azt::app::kExitUsage;
}
