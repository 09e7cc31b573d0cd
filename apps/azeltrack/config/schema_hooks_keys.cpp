// The schema's hook keys: the programs run at a scheduled pass's events (hooks_config.cpp reads
// them; docs/satellites.md "Hooks").
#include <array>

#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<KeySpec, 5> kHooks{{
    {.key = "aos",
     .type = KeyType::TextList,
     .default_toml = "[]",
     .help = "run when a scheduled pass begins: a program's absolute path, or `[\"/path\", "
             "\"argument\", …]`; no shell reads it; empty: none",
     .text_alone = true},
    {.key = "los",
     .type = KeyType::TextList,
     .default_toml = "[]",
     .help = "run when a scheduled pass ends (its LOS, or another pass taking over)",
     .text_alone = true},
    {.key = "pre_position",
     .type = KeyType::TextList,
     .default_toml = "[]",
     .help = "run when the antenna starts for the next pass's AOS point",
     .text_alone = true},
    {.key = "park",
     .type = KeyType::TextList,
     .default_toml = "[]",
     .help = "run when the schedule, with nothing to do, parks the antenna",
     .text_alone = true},
    {.key = "timeout_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.1, 3600.0),
     .default_toml = "30.0",
     .help = "a hook still running this long is stopped: SIGTERM to its process group, SIGKILL "
             "2 s later"},
}};

constexpr std::array<SectionSpec, 1> kSections{{
    {.name = "hooks",
     .chapter = Chapter::Targets,
     .keys = kHooks,
     .title = "Schedule hooks",
     .help = "Programs run at the schedule's events, with the pass in their environment "
             "(`AZT_SAT`, `AZT_NORAD`, `AZT_AOS`, `AZT_LOS`, `AZT_MAX_EL`, `AZT_EVENT`), as the "
             "daemon's user; their exit status and first lines of output go to the journal and "
             "the console's recent events ([satellites.md](satellites.md) \"Hooks\")."},
}};

}  // namespace

std::span<const SectionSpec> hooks_sections() { return kSections; }

}  // namespace azt::app
