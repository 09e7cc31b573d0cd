// `azeltrack serve`: the daemon (docs/daemon.md).
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "azt/astro/time_scales.hpp"
#include "azt/linux/atomic_file.hpp"
#include "azt/linux/self_restart.hpp"
#include "cli/commands.hpp"
#include "common/first_target.hpp"
#include "common/sky_report.hpp"
#include "common/sky_setup.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/config_store.hpp"
#include "config/config_text_edit.hpp"
#include "daemon/daemon.hpp"

namespace azt::app {
namespace {

/// The package's state directory for root (the systemd unit's file: dpkg never prompts about a
/// file it does not ship, so upgrades leave it alone), else the user's config directory.
std::string default_config_path() {
  if (geteuid() == 0) return "/var/lib/azeltrack/azeltrack.toml";
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::string(xdg) + "/azeltrack/azeltrack.toml";
  }
  const char* home = std::getenv("HOME");
  return std::string(home != nullptr ? home : ".") + "/.config/azeltrack/azeltrack.toml";
}

/// The default configuration's text with `[target] name` set to something that is up at
/// `unix_s` (common/first_target.hpp), its comments kept; the reason is logged.
std::string default_config_for(double unix_s) {
  std::string text = default_config_text();
  const ConfigFile file = ConfigFile::parse(text, "the default configuration");
  const DaemonConfig config = daemon_config_from(file);
  const auto ephemeris = open_ephemeris(config.sky.settings.ephemeris);
  const auto sky =
      sky_snapshot(*ephemeris, config.sky.settings, astro::UtcInstant::from_unix_seconds(unix_s));
  if (!sky) return text;
  const FirstTarget first =
      choose_first_target(*sky, config.sky.targets, config.station.el_range.min_deg);
  spdlog::warn("first start: tracking {}: {}", first.name, first.why);
  if (first.name == config.start_target) return text;
  toml::table after = file.root();
  after["target"].as_table()->insert_or_assign("name", first.name);
  return edit_toml_text(text, file.root(), after).value_or(text);
}

/// A first run writes the commented default (the simulated antenna) and uses it. A missing file
/// with a backup beside it is not a first run: ConfigStore recovers the backup.
void write_default_if_missing(const std::string& path, double unix_s) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) || std::filesystem::exists(path + ".bak", ec)) return;
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path(), ec);
  // 0640: it will hold the console's password hash and API token.
  auto written = linux_os::write_file_atomically(path, default_config_for(unix_s), 0640);
  if (!written)
    throw UsageError("cannot write the default configuration: " + written.error().message);
  spdlog::warn("no configuration at {}: wrote the default (simulated antenna); edit it and restart",
               path);
}

void set_log_level(const std::string& level) {
  spdlog::set_level(level == "debug"  ? spdlog::level::debug
                    : level == "warn" ? spdlog::level::warn
                                      : spdlog::level::info);
}

}  // namespace

Runner add_serve_command(CLI::App& app) {
  auto opts = std::make_shared<DaemonOptions>();
  CLI::App* cmd = app.add_subcommand(
      "serve", "Run the daemon: control loop, rotctld, serial and PstRotator servers");
  cmd->add_option("--config", opts->config_path,
                  "Configuration file (default: /var/lib/azeltrack/azeltrack.toml as root, else "
                  "~/.config/azeltrack/azeltrack.toml; written with defaults if missing)");
  cmd->add_option("--run-for", opts->run_for_s, "Stop after this many seconds (tests)")
      ->check(CLI::Range(0.0, 1e9));
  auto utc_start = std::make_shared<std::string>();
  cmd->add_option("--utc-start", *utc_start,
                  "Tests: the daemon's clock starts at this UTC instant (ISO 8601, "
                  "2026-03-20T12:00:00Z) instead of the system's, so its sky is the same at any "
                  "hour");
  cmd->add_option("--update-inbox", opts->update_inbox,
                  "Folder where a package uploaded on the console's Software page is left for "
                  "the root update helper (the package's unit: /var/lib/azeltrack/update)");
  cmd->add_option("--update-status", opts->update_status,
                  "The update helper's status file (the package's unit: "
                  "/var/lib/azeltrack-update/status)");
  return [opts, utc_start] {
    if (!utc_start->empty()) {
      auto parsed = astro::parse_iso8601_utc(*utc_start);
      if (!parsed) throw UsageError("--utc-start: " + parsed.error().message);
      opts->utc_start_unix_s = parsed->unix_seconds();
    }
    if (opts->config_path.empty()) opts->config_path = default_config_path();
    write_default_if_missing(opts->config_path,
                             opts->utc_start_unix_s.value_or(utc_now().unix_seconds()));
    ConfigStore store = ConfigStore::open(opts->config_path);
    // Loudly: a fallback to the backup means the primary file was corrupt.
    for (const auto& notice : store.notices()) spdlog::warn("{}", notice);
    if (auto removed = store.remove_stale_temps()) spdlog::warn("{}", *removed);
    set_log_level(store.config().log_level);
    const int status = run_daemon(store, *opts);
    if (status != linux_os::kExitRestart || linux_os::started_by_systemd()) return status;
    // Not a service: nobody else would start it again. The daemon has stopped the motors,
    // closed its servers and released its devices; the same command starts afresh.
    spdlog::info("restarting: running the same command again");
    spdlog::default_logger()->flush();
    const auto failed = linux_os::reexec_self();
    throw UsageError("cannot restart: " + failed.error().message);
  };
}

}  // namespace azt::app
