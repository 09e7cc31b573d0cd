// `azeltrack schedule` (docs/satellites.md "The schedule"): the plan the station would follow
// over the next hours from the configuration's [[schedule]], with the daemon's own planner.
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "common/horizon_mask_option.hpp"
#include "common/sky_setup.hpp"
#include "common/usage_error.hpp"
#include "config/daemon_config.hpp"
#include "schedule/satellite_schedule.hpp"

namespace azt::app {
namespace {

struct ScheduleOptions {
  std::string config;
  std::string tle;
  std::string from;
  std::string hours = "24";
  bool json = false;
};

/// --tle, else [satellites] file (relative to the configuration's folder, as the daemon reads it).
std::string catalogue_path(const ScheduleOptions& o, const DaemonConfig& c) {
  if (!o.tle.empty()) return o.tle;
  if (c.satellites.file.empty()) {
    throw UsageError("schedule: no element sets: give --tle FILE or set [satellites] file");
  }
  const std::filesystem::path file(c.satellites.file);
  if (file.is_absolute()) return file.string();
  return (std::filesystem::path(o.config).parent_path() / file).string();
}

void print_text(const nlohmann::json& plan) {
  for (const auto& s : plan["plan"]) {
    std::cout << s["from"].get<std::string>() << " – " << s["to"].get<std::string>() << "  "
              << s["kind"].get<std::string>();
    if (!s["sat"].is_null()) std::cout << "  " << s["sat"].get<std::string>();
    std::cout << '\n';
  }
  if (plan["plan"].empty()) std::cout << "nothing to do\n";
}

int run_schedule(const ScheduleOptions& o) {
  if (o.config.empty()) throw UsageError("schedule: --config FILE is required");
  const DaemonConfig c = load_daemon_config(o.config);
  const auto& entries = c.schedule;
  if (entries.empty()) throw UsageError("schedule: " + o.config + " has no [[schedule]] table");
  const double hours = parse_number_option("--hours", o.hours);
  if (!(hours > 0.0 && hours <= 24.0 * 7)) throw UsageError("--hours must be in (0, 168]");
  astro::UtcInstant from = utc_now();
  if (!o.from.empty()) {
    auto t = astro::parse_iso8601_utc(o.from);
    if (!t) throw UsageError("--from: " + t.error().message);
    from = *t;
  }
  const ScheduleSite site{c.sky.settings.observer, c.sky.settings.dut1_s,
                          parse_horizon_mask("[satellites] mask", c.satellites.mask)};
  const auto plan =
      plan_satellite_schedule(SatelliteCatalogue::load(catalogue_path(o, c)), entries, site,
                              schedule_rules_of(c), from, hours, c.park[0].position);
  if (o.json) {
    std::cout << plan.dump() << '\n';
  } else {
    print_text(plan);
  }
  return 0;
}

}  // namespace

Runner add_schedule_command(CLI::App& app) {
  auto opts = std::make_shared<ScheduleOptions>();
  CLI::App* cmd = app.add_subcommand(
      "schedule", "The satellite schedule's plan: track, pre-position, park, power off");
  cmd->add_option("--config", opts->config, "The configuration with [[schedule]]")->required();
  cmd->add_option("--tle", opts->tle, "Element sets (default: [satellites] file)");
  cmd->add_option("--from", opts->from, "Start, UTC ISO 8601; default now");
  cmd->add_option("--hours", opts->hours, "Length of the plan, hours (default 24)");
  cmd->add_flag("--json", opts->json, "JSON output");
  return [opts] { return run_schedule(*opts); };
}

}  // namespace azt::app
