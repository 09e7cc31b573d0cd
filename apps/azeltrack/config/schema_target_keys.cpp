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

constexpr std::array<KeySpec, 14> kSatellites{{
    {.key = "file",
     .type = KeyType::Text,
     .default_note = "none",
     .help = "element sets (TLE or OMM) the daemon tracks satellites from, relative to the "
             "configuration's directory, merged with `sources`; re-read when it changes (replace "
             "it atomically: write a temp file and rename)"},
    {.key = "sources",
     .type = KeyType::TextList,
     .default_toml = "[]",
     .help = "URLs of element sets fetched at start and every `refresh_h`, in order: CelesTrak GP "
             "queries (`\"https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=tle\"`, "
             "or `FORMAT=json`, `csv`, `xml`), SatNOGS DB, AMSAT's `nasabare.txt`, `file://`; each "
             "download is checked before use and a failed one keeps its previous sets "
             "([satellites.md](satellites.md))"},
    {.key = "refresh_h",
     .type = KeyType::Number,
     .unit = "h",
     .range = closed(2.0, 720.0),
     .default_toml = "12.0",
     .help = "how often `sources` are fetched (CelesTrak updates every 2 h and asks for a few "
             "downloads a day)"},
    {.key = "stale_days",
     .type = KeyType::Number,
     .unit = "days",
     .range = above_up_to(0.0, 3650.0),
     .default_toml = "14.0",
     .help = "elements further than this from their epoch mark a satellite's passes stale"},
    {.key = "refuse_days",
     .type = KeyType::Number,
     .unit = "days",
     .range = above_up_to(0.0, 3650.0),
     .default_toml = "60.0",
     .help = "elements further than this from their epoch are not tracked (the reason is shown)"},
    {.key = "idle_park_min",
     .type = KeyType::Number,
     .unit = "min",
     .range = closed(0.1, 1440.0),
     .default_toml = "10.0",
     .help = "the schedule parks after this long with nothing to do, then switches "
             "`[hardware.power]` off until the next pre-position"},
    {.key = "ca_file",
     .type = KeyType::Text,
     .default_note = "the system's CAs",
     .help = "a PEM file of the certificate authorities HTTPS sources are checked against"},
    {.key = "proxy",
     .type = KeyType::Text,
     .default_note = "the `https_proxy` environment variable, or none",
     .help = "proxy for the downloads: `\"http://host:3128\"`, `\"socks5h://host:1080\"`"},
    {.key = "connect_timeout_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.1, 300.0),
     .default_toml = "20.0",
     .help = "a source that does not connect within this fails (its previous sets stay)"},
    {.key = "timeout_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.1, 3600.0),
     .default_toml = "120.0",
     .help = "a download that takes longer than this in all fails (a stalled server)"},
    {.key = "max_mb",
     .type = KeyType::Number,
     .unit = "MB",
     .range = closed(0.01, 256.0),
     .default_toml = "32.0",
     .help = "a download larger than this fails (a whole CelesTrak group such as `active` is "
             "megabytes)"},
    {.key = "max_redirects",
     .type = KeyType::Integer,
     .range = closed(0.0, 20.0),
     .default_toml = "5",
     .help = "redirects followed before a download fails (a redirect loop)"},
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
