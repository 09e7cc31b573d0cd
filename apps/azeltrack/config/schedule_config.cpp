#include "config/schedule_config.hpp"

#include "config/config_file.hpp"

namespace azt::app {

std::vector<ScheduleEntryConfig> schedule_config_from(const ConfigFile& file) {
  std::vector<ScheduleEntryConfig> out;
  for (const ConfigSection& s : file.section_array("schedule")) {
    ScheduleEntryConfig e;
    e.sat = s.text("sat").value_or("");
    if (e.sat.empty()) s.fail("sat", "is required: a satellite's name or NORAD number");
    for (const auto& other : out) {
      if (other.sat == e.sat) s.fail("sat", "\"" + e.sat + "\" is listed twice");
    }
    e.min_el_deg = s.number("min_el_deg").value_or(0.0);
    // The schema has refused anything but its two choices already.
    e.preempt = schedule::parse_preempt(s.text("preempt").value_or("take_over"))
                    .value_or(schedule::Preempt::TakeOver);
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace azt::app
