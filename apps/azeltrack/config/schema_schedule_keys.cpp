// The schema's schedule keys: the satellites the station works by itself, in priority order
// (schedule/schedule_config.cpp reads them; docs/satellites.md "The schedule").
#include <array>

#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<std::string_view, 2> kPreempt{"take_over", "finish"};

constexpr std::array<KeySpec, 3> kSchedule{{
    {.key = "sat",
     .type = KeyType::Text,
     .help = "required: a satellite of the catalogue, by name (case-insensitive, or a unique "
             "prefix) or NORAD number; the first table has the highest priority",
     .applies = Applies::Live},
    {.key = "min_el_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(0.0, 90.0),
     .default_toml = "0.0",
     .help = "a pass whose highest point is lower is not worked",
     .applies = Applies::Live},
    {.key = "preempt",
     .type = KeyType::Choice,
     .choices = kPreempt,
     .default_toml = "\"take_over\"",
     .help = "at this satellite's AOS, a running pass of lower priority: `take_over` (this one "
             "starts at once) or `finish` (it waits for that pass's LOS)",
     .applies = Applies::Live},
}};

constexpr std::array<SectionSpec, 1> kSections{{
    {.name = "schedule",
     .chapter = Chapter::Targets,
     .array_of_tables = true,
     .keys = kSchedule,
     .title = "The satellite schedule",
     .help = "The satellites the station follows by itself, highest priority first "
             "([satellites.md](satellites.md) \"The schedule\"); `azeltrack schedule` prints the "
             "plan."},
}};

}  // namespace

std::span<const SectionSpec> schedule_sections() { return kSections; }

}  // namespace azt::app
