#pragma once

#include <CLI/CLI.hpp>

#include <functional>

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

/// Parses a finite decimal number given to `option`; throws UsageError otherwise
/// (CLI11 would accept "nan" and "inf").
double parse_number_option(const std::string& option, const std::string& text);

}  // namespace azt::app
