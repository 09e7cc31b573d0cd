#pragma once
// The schedule over a catalogue (docs/satellites.md "The schedule"): the passes of each
// [[schedule]] satellite found by SGP4 over the station's horizon, handed to the core's planner,
// and the plan as `azeltrack schedule --json` prints it. The daemon's follower plans with this
// same code.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/astro/observer.hpp"
#include "azt/astro/time_scales.hpp"
#include "azt/orbit/passes.hpp"
#include "azt/schedule/pass_schedule.hpp"
#include "config/schedule_config.hpp"
#include "satellites/satellite_catalogue.hpp"

namespace azt::app {

struct ScheduleSite {
  astro::Observer site;
  double dut1_s = 0.0;
  orbit::HorizonMask mask;
};

/// The plan for [from, from + hours): {"plan": [{"kind", "sat", "norad", "from", "to"}]} in time
/// order (`sat` and `norad` null for park and power_off), and "passes" searched per satellite.
/// Throws UsageError for a scheduled satellite the catalogue does not hold.
nlohmann::json plan_satellite_schedule(const SatelliteCatalogue& catalogue,
                                       const std::vector<ScheduleEntryConfig>& entries,
                                       const ScheduleSite& station,
                                       const schedule::ScheduleRules& rules,
                                       const astro::UtcInstant& from, double hours,
                                       control::AzEl start_sky);

}  // namespace azt::app
