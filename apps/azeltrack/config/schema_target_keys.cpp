// The schema's target keys: what to track at start, the satellites and the spacecraft
// (daemon_config.cpp and sky_config.cpp read them).
#include <array>

#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<KeySpec, 1> kTarget{{
    {.key = "name",
     .type = KeyType::Text,
     .default_toml = "\"moon\"",
     .help = "what `serve` tracks at start: `sun`, `moon`, the name of a radio source in `[sky] "
             "sources` (case-insensitive) or of a `[[spacecraft]]`, `\"sat:NAME_OR_NORAD\"` (a "
             "satellite of `[satellites] file`), or `\"stop\"`"},
}};

constexpr std::array<KeySpec, 3> kSatellites{{
    {.key = "file",
     .type = KeyType::Text,
     .default_note = "none",
     .help = "element sets (TLE or OMM) the daemon tracks satellites from, relative to the "
             "configuration's directory; re-read when it changes (replace it atomically: write a "
             "temp file and rename)"},
    {.key = "mask",
     .type = KeyType::Text,
     .default_toml = "\"0\"",
     .help = "the horizon for passes: one elevation, or `\"AZ:MIN_EL,…\"` sectors "
             "(`\"0:5,90:12,200:3\"`)"},
    {.key = "beamwidth_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = above_up_to(0.0, 180.0),
     .default_toml = "20.0",
     .help = "the satellite antenna's half-power beamwidth: a moment of a pass further than half "
             "of it from the satellite counts as lost; a pass the mount cannot follow throughout "
             "is planned to lose the least time and its loss reported before AOS "
             "([satellites.md](satellites.md))"},
}};

constexpr std::array<KeySpec, 4> kSpacecraft{{
    {.key = "name",
     .type = KeyType::Text,
     .help = "required: the name it is tracked by, like any target"},
    {.key = "file",
     .type = KeyType::Text,
     .help = "required: a JPL Horizons vector table (`EPHEM_TYPE='VECTORS'`, geocentric "
             "`CENTER='500@399'`, ICRF, geometric, CSV or text, KM-S/AU-D), relative to the "
             "configuration's directory, read and checked at start"},
    {.key = "description",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "shown beside the name"},
    {.key = "frequency_mhz",
     .type = KeyType::Number,
     .unit = "MHz",
     .range = closed(0.0, 1e6),
     .default_toml = "0.0",
     .help = "its downlink, for the Doppler shown; 0: none"},
}};

constexpr std::array<SectionSpec, 3> kSections{{
    {.name = "target",
     .chapter = Chapter::Targets,
     .keys = kTarget,
     .title = "The target at start"},
    {.name = "satellites",
     .chapter = Chapter::Targets,
     .keys = kSatellites,
     .title = "Satellites",
     .help = "SGP4 tracking and pass plans ([satellites.md](satellites.md))."},
    {.name = "spacecraft",
     .chapter = Chapter::Targets,
     .array_of_tables = true,
     .keys = kSpacecraft,
     .title = "Spacecraft",
     .help = "Spacecraft from JPL Horizons (the DSN page), one table each."},
}};

}  // namespace

std::span<const SectionSpec> target_sections() { return kSections; }

}  // namespace azt::app
