#pragma once
// [[schedule]] (docs/satellites.md "The schedule"): the satellites the station works by itself,
// highest priority first.

#include <string>
#include <vector>

#include "azt/schedule/pass_schedule.hpp"

namespace azt::app {

class ConfigFile;

struct ScheduleEntryConfig {
  std::string sat;  ///< a name (or a unique prefix) or a NORAD number of the catalogue
  double min_el_deg = 0.0;
  schedule::Preempt preempt = schedule::Preempt::TakeOver;
};

/// Throws UsageError naming the table and key on an invalid entry.
std::vector<ScheduleEntryConfig> schedule_config_from(const ConfigFile& file);

}  // namespace azt::app
