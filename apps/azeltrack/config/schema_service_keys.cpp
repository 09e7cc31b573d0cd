// The schema's keys of what the station knows of its surroundings and tells other programs: the
// GPS, the clock, the scan receiver, azel.dat (gps_config.cpp, time_config.cpp,
// receiver_config.cpp and export_config.cpp read them).
#include <array>

#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<KeySpec, 6> kGps{{
    {.key = "enabled",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "watch the GPS receiver through gpsd: its state in `/api/state` `gps`"},
    {.key = "gpsd",
     .type = KeyType::Text,
     .default_toml = "\"127.0.0.1:2947\"",
     .help = "gpsd's address: `\"HOST:PORT\"`, `\"[IPV6]:PORT\"` or a host alone"},
    {.key = "use_position",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the average of a 3D fix held `hold_s` becomes the station's position, saved as "
             "`[station] lat_deg`/`lon_deg`/`alt_m`"},
    {.key = "min_sats",
     .type = KeyType::Integer,
     .range = closed(3.0, 64.0),
     .default_toml = "4",
     .help = "the satellites a surveyed fix needs"},
    {.key = "hold_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.0, 86400.0),
     .default_toml = "60.0",
     .help = "how long the fix is averaged (receiver time)"},
    {.key = "jump_m",
     .type = KeyType::Number,
     .unit = "m",
     .range = closed(1.0, 1e6),
     .default_toml = "100.0",
     .help = "a survey further than this from the station is not adopted while tracking"},
}};

constexpr std::array<KeySpec, 6> kTime{{
    {.key = "chronyc",
     .type = KeyType::Text,
     .default_toml = "\"chronyc\"",
     .help = "the program that asks chronyd for its tracking and sources"},
    {.key = "chrony_socket",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "chronyc's `-h`: a command socket or host; empty for chronyc's default"},
    {.key = "poll_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(1.0, 300.0),
     .default_toml = "5.0",
     .help = "how often chrony, the kernel's adjtimex verdict and the RTC are checked"},
    {.key = "rtc",
     .type = KeyType::Text,
     .default_toml = "\"/dev/rtc0\"",
     .help = "the battery-backed clock whose presence is reported"},
    {.key = "manage_chrony",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the console may set chrony's upstream NTP servers in `sources_file`, and chronyd "
             "reloads them"},
    {.key = "sources_file",
     .type = KeyType::Text,
     .default_toml = "\"/var/lib/azeltrack/chrony/azeltrack.sources\"",
     .help = "an absolute path ending in `.sources` (chrony's sourcedir reads only those)"},
}};

constexpr std::array<std::string_view, 4> kReceiverSources{"none", "rtl_power", "udp", "sim"};

constexpr std::array<KeySpec, 8> kReceiver{{
    {.key = "source",
     .type = KeyType::Choice,
     .choices = kReceiverSources,
     .default_toml = "\"none\"",
     .help = "`rtl_power`: its CSV lines from the FIFO or file at `path` (`rtl_power -f … -i 1 - > "
             "PATH`, one hop); `udp`: datagrams of one dB value per line on `bind:port`; `sim`: "
             "the simulated receiver (`[sim.receiver]`, only with the `sim` backend), hearing the "
             "true beam through `[sim.mount_errors]`"},
    {.key = "path",
     .type = KeyType::Text,
     .help = "`rtl_power`, required: the absolute path of the FIFO or file it writes"},
    {.key = "bind",
     .type = KeyType::Text,
     .default_toml = "\"127.0.0.1\"",
     .help = "`udp`: the address datagrams arrive at"},
    {.key = "port",
     .type = KeyType::Integer,
     .range = closed(0.0, 65535.0),
     .default_note = "none",
     .help = "`udp`, required: the port datagrams arrive at"},
    {.key = "stale_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.1, 60.0),
     .default_toml = "2.0",
     .help = "the receiver is silent after this long without a reading"},
    {.key = "tsys_k",
     .type = KeyType::Number,
     .unit = "K",
     .range = above_up_to(0.0, 100000.0),
     .default_note = "not given",
     .help = "the system noise temperature on cold sky: with `[station] dish_m` and "
             "`efficiency`, which sources a calibration scan can hear "
             "([calibration.md](calibration.md))"},
    {.key = "bandwidth_hz",
     .type = KeyType::Number,
     .unit = "Hz",
     .range = above_up_to(0.0, 1e10),
     .default_note = "not given: 0.1 dB a reading assumed",
     .help = "the bandwidth each reading integrates: with `integration_s`, the scatter of a "
             "reading of an ideal radiometer, 10·log10(1 + 1/√(B·τ)), for the sources' estimate"},
    {.key = "integration_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = above_up_to(0.0, 60.0),
     .default_toml = "1.0",
     .help = "the time one reading integrates (rtl_power's `-i`): the readings a scan point "
             "averages are its dwell over this"},
}};

constexpr std::array<KeySpec, 2> kExport{{
    {.key = "azel_dat",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "WSJT-X's azel.dat (Moon, Sun, tracked source, echo Doppler at the band), rewritten "
             "every second at this absolute file path for the programs that read it "
             "([eme.md](eme.md)); empty: none"},
    {.key = "azel_dat_pol_line",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "azel.dat gains WSJT-X's optional fifth line (Dpol, MNR, Dgrd, the self and DX echo "
             "widths, its AzElExtraLines); off, as WSJT-X writes it by default"},
}};

constexpr std::array<SectionSpec, 4> kSections{{
    {.name = "gps",
     .chapter = Chapter::Services,
     .keys = kGps,
     .title = "The GPS receiver",
     .help = "Through gpsd ([gps.md](gps.md))."},
    {.name = "time",
     .chapter = Chapter::Services,
     .keys = kTime,
     .title = "The clock",
     .help = "The clock watched through chrony, in `/api/state` `time` with a banner when not "
             "synchronised ([time.md](time.md))."},
    {.name = "receiver",
     .chapter = Chapter::Services,
     .keys = kReceiver,
     .title = "The receiver of pointing scans",
     .help = "Its readings, and the malformed and missing ones, in `/api/state` `receiver` "
             "([calibration.md](calibration.md))."},
    {.name = "export",
     .chapter = Chapter::Services,
     .keys = kExport,
     .title = "Files for other programs"},
}};

}  // namespace

std::span<const SectionSpec> service_sections() { return kSections; }

}  // namespace azt::app
