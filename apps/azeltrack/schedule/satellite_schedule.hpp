#pragma once
// The schedule over a catalogue (docs/satellites.md "The schedule"): the passes of each
// [[schedule]] satellite found by SGP4 over the station's horizon, handed to the core's planner,
// and the plan as `azeltrack schedule --json` and GET /api/schedule show it. The daemon's
// follower (schedule_follower.hpp) plans with this same code.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/astro/observer.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/orbit/satellite.hpp"
#include "azt/schedule/pass_schedule.hpp"
#include "config/daemon_config.hpp"
#include "config/schedule_config.hpp"
#include "satellites/satellite_catalogue.hpp"

namespace azt::app {

struct ScheduleSite {
  astro::Observer site;
  double dut1_s = 0.0;
  orbit::HorizonMask mask;
};

/// The [[schedule]] entries the catalogue holds, in priority order, with their element sets
/// copied: the daemon plans off the loop while a new catalogue may replace the old one.
struct ScheduledSatellites {
  std::vector<schedule::Priority> priorities;  ///< `sat` is the catalogue's name for it
  std::vector<orbit::Satellite> sats;          ///< one per priority
  std::vector<std::string> missing;            ///< "NAME: why" for entries it does not hold
};
ScheduledSatellites scheduled_satellites(const SatelliteCatalogue& catalogue,
                                         const std::vector<ScheduleEntryConfig>& entries);

/// The station's own figures for the planner: park slot 1, the axes' full-speed rates, the idle
/// time, and the power relay with its lead. The CLI and the daemon plan with the same.
schedule::ScheduleRules schedule_rules_of(const DaemonConfig& config);

/// A pass of a scheduled satellite, Unix UTC seconds.
struct PlannedPass {
  std::size_t priority = 0;
  double aos_unix_s = 0.0;
  double los_unix_s = 0.0;
  double max_el_deg = 0.0;
};

/// The plan over [from, from + hours), times in Unix UTC seconds.
struct SchedulePlan {
  double from_unix_s = 0.0;
  double hours = 0.0;
  std::vector<schedule::Priority> priorities;
  std::vector<PlannedPass> passes;  ///< every pass found, worked or not
  std::vector<schedule::PlanStep> steps;
  std::vector<std::string> errors;  ///< satellites whose pass search failed (a decayed orbit)
};

/// Plans from `start` (Unix UTC seconds) over `hours`.
SchedulePlan plan_schedule_over(const ScheduledSatellites& sats, const ScheduleSite& station,
                                const schedule::ScheduleRules& rules,
                                const schedule::PlanStart& start, double hours);

/// {"from", "hours", "plan": [{"kind", "sat", "norad", "from", "to"}], "passes": [{"sat",
/// "norad", "aos", "los", "max_el_deg", "worked"}]}: `sat` and `norad` null for park and
/// power_off; `worked` false for a pass below its entry's minimum elevation.
nlohmann::json plan_json(const SchedulePlan& plan);

/// One step as the plan shows it: {"kind", "sat", "norad", "from", "to"}.
nlohmann::json plan_step_json(const SchedulePlan& plan, const schedule::PlanStep& step);

/// The pass a step is about: the one a track follows or a pre-position prepares; null for
/// park and power_off.
const PlannedPass* pass_of(const SchedulePlan& plan, const schedule::PlanStep& step);

/// `azeltrack schedule`: the plan_json() of a fresh plan from `from`, the antenna idle at
/// `start_sky`. Throws UsageError for a scheduled satellite the catalogue does not hold.
nlohmann::json plan_satellite_schedule(const SatelliteCatalogue& catalogue,
                                       const std::vector<ScheduleEntryConfig>& entries,
                                       const ScheduleSite& station,
                                       const schedule::ScheduleRules& rules,
                                       const astro::UtcInstant& from, double hours,
                                       control::AzEl start_sky);

}  // namespace azt::app
