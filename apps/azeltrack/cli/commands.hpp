#pragma once

#include <CLI/CLI.hpp>

#include <functional>

#include "common/usage_error.hpp"

namespace azt::app {

/// Each subcommand registers its options on `app` and returns what to run after parsing.
/// The runner returns the process exit code; it throws UsageError for bad values.
using Runner = std::function<int()>;

Runner add_sky_command(CLI::App& app);
Runner add_locator_command(CLI::App& app);
Runner add_watch_command(CLI::App& app);
Runner add_simulate_command(CLI::App& app);
Runner add_hub_command(CLI::App& app);
Runner add_serve_command(CLI::App& app);
Runner add_config_command(CLI::App& app);
Runner add_web_command(CLI::App& app);
Runner add_seq_sim_command(CLI::App& app);
Runner add_sat_command(CLI::App& app);
Runner add_passes_command(CLI::App& app);
Runner add_moon_windows_command(CLI::App& app);
Runner add_schedule_command(CLI::App& app);
Runner add_pointing_command(CLI::App& app);

}  // namespace azt::app
