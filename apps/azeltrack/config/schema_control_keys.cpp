// The schema's control keys: the movement, the travel, the position corrections and pointing
// model, the park slots and the mount's axes (station_setup_config.cpp, pointing_config.cpp,
// mount_config.cpp and daemon_config.cpp read them).
#include <array>

#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<std::string_view, 2> kOutOfRange{"hold", "park"};

constexpr std::array<KeySpec, 9> kControl{{
    {.key = "window_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(0.0, 2.0),
     .default_toml = "0.0",
     .help = "movement window: no motion while |error| ≤ window + 1 LSB"},
    {.key = "ramp_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.0, 30.0),
     .default_toml = "1.0",
     .help = "soft start and stop: the time for the drive to go from 0 to 100 %"},
    {.key = "tracking_speed",
     .type = KeyType::Number,
     .range = above_up_to(0.0, 1.0),
     .default_toml = "0.5",
     .help = "fraction of full speed within `fast_zone_deg` of the target"},
    {.key = "fast_zone_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = above(0.0),
     .default_toml = "3.0",
     .help = "beyond this pointing error, full speed"},
    {.key = "lead",
     .type = KeyType::Boolean,
     .default_toml = "true",
     .help = "lead a moving target across the window (about half the motor starts)"},
    {.key = "tick_hz",
     .type = KeyType::Number,
     .unit = "Hz",
     .range = closed(1.0, 200.0),
     .default_toml = "20",
     .help = "control loop rate"},
    {.key = "out_of_range",
     .type = KeyType::Choice,
     .choices = kOutOfRange,
     .default_toml = "\"hold\"",
     .help = "when the tracked target is below the elevation limit: `hold` where the antenna is, "
             "or `park`"},
    {.key = "park_az_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = from_below(0.0, 360.0),
     .default_toml = "180.0",
     .help = "the park azimuth for `out_of_range = \"park\"`; in `serve` it is park slot 1 unless "
             "a `[[park]]` table replaces that slot"},
    {.key = "park_el_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_note = "el_min_deg",
     .help = "the park elevation for `out_of_range = \"park\"`, inside `[geometry]`"},
}};

constexpr std::array<KeySpec, 4> kGeometry{{
    {.key = "az_min_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_toml = "0.0",
     .help = "azimuth travel's start in mount degrees; the travel spans 360 to 720° (0…450, "
             "−180…540 …)"},
    {.key = "az_max_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_toml = "360.0",
     .help = "azimuth travel's end; `az_max_deg − az_min_deg` is 360 to 720"},
    {.key = "el_min_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(-10.0, 180.0),
     .default_toml = "0.0",
     .help = "elevation travel's lower end, below `el_max_deg`"},
    {.key = "el_max_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(-10.0, 180.0),
     .default_toml = "90.0",
     .help = "elevation travel's upper end (above 90 for flip mounts)"},
}};

constexpr std::array<KeySpec, 5> kCorrections{{
    {.key = "az_offset_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = within(360.0),
     .default_toml = "0.0",
     .help = "added to the azimuth encoder's readings (the seed's Offset screen)",
     .applies = Applies::Live},
    {.key = "el_offset_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = within(180.0),
     .default_toml = "0.0",
     .help = "added to the elevation encoder's readings",
     .applies = Applies::Live},
    {.key = "az_user_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = within(10.0),
     .default_toml = "0.0",
     .help = "the operator's azimuth correction in 0.01° steps (±): + points clockwise",
     .applies = Applies::Live},
    {.key = "el_user_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = within(10.0),
     .default_toml = "0.0",
     .help = "the operator's elevation correction in 0.01° steps (UP / DWN): + points higher",
     .applies = Applies::Live},
    {.key = "tilt_el_deg",
     .type = KeyType::NumberList,
     .unit = "°",
     .range = within(5.0),
     .items = {60, 60},
     .default_note = "60 zeros",
     .help = "the tilt table: elevation corrections at azimuth 0, 6, … 354°, interpolated",
     .applies = Applies::Live},
}};

/// One term of the pointing model ([calibration.md](calibration.md)).
constexpr KeySpec pointing_term(std::string_view key, std::string_view help) {
  return {.key = key,
          .type = KeyType::Number,
          .unit = "°",
          .range = within(10.0),
          .default_toml = "0.0",
          .help = help,
          .applies = Applies::Live};
}

constexpr std::array<KeySpec, 7> kPointing{{
    pointing_term("ia_deg", "IA: azimuth encoder zero (a − A = +IA)"),
    pointing_term("ie_deg", "IE: elevation encoder zero (e − E = +IE)"),
    pointing_term("ca_deg", "CA: beam clockwise of square to the elevation axis (collimation)"),
    pointing_term("npae_deg", "NPAE: elevation axis raised at its clockwise end"),
    pointing_term("an_deg", "AN: azimuth axis tilted towards the north"),
    pointing_term("aw_deg", "AW: azimuth axis tilted towards the east"),
    pointing_term("sag_deg", "SAG: the beam droops by SAG·cos e"),
}};

constexpr std::array<KeySpec, 3> kPark{{
    {.key = "name",
     .type = KeyType::Text,
     .default_note = "park N",
     .help = "the slot's name on the console and panel",
     .applies = Applies::Live},
    {.key = "az_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = from_below(0.0, 360.0),
     .default_toml = "180.0",
     .help = "the slot's azimuth",
     .applies = Applies::Live},
    {.key = "el_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_note = "el_min_deg",
     .help = "the slot's elevation, inside `[geometry]`",
     .applies = Applies::Live},
}};

/// [mount.az] and [mount.el] differ only in the axis's default speed.
constexpr std::array<KeySpec, 5> mount_keys(std::string_view max_rate_default) {
  return {{
      {.key = "max_rate_deg_s",
       .type = KeyType::Number,
       .unit = "°/s",
       .range = closed(0.01, 90.0),
       .default_toml = max_rate_default,
       .help = "the real axis's speed at full drive: what the controller and the supervisors plan "
               "with, on every backend"},
      {.key = "encoder_bits",
       .type = KeyType::Integer,
       .range = closed(9.0, 16.0),
       .default_toml = "12",
       .help = "absolute encoder resolution (the EncoderHub's jumpers; a hub frame reporting other "
               "bits is a fault naming both)"},
      {.key = "time_constant_s",
       .type = KeyType::Number,
       .unit = "s",
       .range = closed(0.01, 10.0),
       .default_toml = "0.3",
       .help = "the motor's speed response, as the controller allows for it"},
      {.key = "min_duty",
       .type = KeyType::Number,
       .range = from_below(0.0, 0.9),
       .default_toml = "0.1",
       .help = "drive below which the motor does not turn (stiction)"},
      {.key = "backlash_deg",
       .type = KeyType::Number,
       .unit = "°",
       .range = closed(0.0, 5.0),
       .default_toml = "0.05",
       .help = "gear play"},
  }};
}

constexpr auto kMountAz = mount_keys("1.5");

/// [mount.el]: an axis as [mount.az] describes one, or an elevation that does not move.
constexpr std::array<KeySpec, 7> mount_el_keys() {
  const auto axis = mount_keys("1.0");
  return {{axis[0],
           axis[1],
           axis[2],
           axis[3],
           axis[4],
           {.key = "fixed_deg",
            .type = KeyType::Number,
            .unit = "°",
            .range = closed(-5.0, 90.0),
            .default_note = "none: the elevation is driven",
            .help = "an elevation that does not move: a fixed-elevation EME array's angle, or 0 "
                    "for an azimuth-only rotator. The station then needs no elevation drive or "
                    "sensor, tracks in azimuth only and reports this angle to every client "
                    "([eme.md](eme.md) \"Fixed-elevation arrays\")"},
           {.key = "beam_width_deg",
            .type = KeyType::Number,
            .unit = "°",
            .range = closed(1.0, 90.0),
            .default_toml = "20.0",
            .help = "with `fixed_deg`: the array's vertical half-power beam width; a target is "
                    "in the beam within half of it above or below `fixed_deg` (`moon-windows`, "
                    "the console's planner, `/api/state` `target_in_beam`)"}}};
}

constexpr auto kMountEl = mount_el_keys();

/// [mount.pol]: an axis as [mount.az] describes one, with its travel and window.
constexpr std::array<KeySpec, 8> mount_pol_keys() {
  const auto axis = mount_keys("2.0");
  return {{axis[0],
           axis[1],
           axis[2],
           axis[3],
           axis[4],
           {.key = "min_deg",
            .type = KeyType::Number,
            .unit = "°",
            .range = closed(-360.0, 360.0),
            .default_toml = "-95.0",
            .help = "the feed's travel, in degrees from level (clockwise seen from behind the "
                    "antenna); at least 180° wide, so every linear polarisation is reachable"},
           {.key = "max_deg",
            .type = KeyType::Number,
            .unit = "°",
            .range = closed(-360.0, 360.0),
            .default_toml = "95.0",
            .help = "the travel's other end"},
           {.key = "window_deg",
            .type = KeyType::Number,
            .unit = "°",
            .range = closed(0.0, 5.0),
            .default_toml = "0.5",
            .help = "the pol axis's movement window (`[control] window_deg` is az and el's)"}}};
}

constexpr auto kMountPol = mount_pol_keys();

constexpr std::array<std::string_view, 6> kPolModes{"off",  "fixed", "manual",
                                                    "self", "dx",    "split"};

constexpr std::array<KeySpec, 5> kPol{{
    {.key = "mode",
     .type = KeyType::Choice,
     .choices = kPolModes,
     .default_toml = "\"off\"",
     .help = "what the feed follows ([eme.md](eme.md)): `off` (held), `fixed` (`fixed_deg`), "
             "`manual` (the operator's angle), `self` (our own echo), `dx` (Dpol to `[sky] "
             "dx_grid` + `dx_offset_deg`), `split` (as `dx` receiving; G3SEK's TX = 2·Dpol − RX "
             "transmitting)",
     .applies = Applies::Live},
    {.key = "fixed_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = within(180.0),
     .default_toml = "0.0",
     .help = "the feed angle of `fixed`, degrees from level",
     .applies = Applies::Live},
    {.key = "self_offset_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = within(180.0),
     .default_toml = "0.0",
     .help = "`self`: the Faraday correction peaked on our own echo",
     .applies = Applies::Live},
    {.key = "dx_offset_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = within(180.0),
     .default_toml = "0.0",
     .help = "`dx` and `split`: the correction peaked on the DX station's signal, added to Dpol",
     .applies = Applies::Live},
    {.key = "hold_while_keyed",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "give the feed no new angle while the transmitter is keyed (it holds), in every "
             "mode",
     .applies = Applies::Live},
}};

constexpr std::array<SectionSpec, 10> kSections{{
    {.name = "control",
     .chapter = Chapter::Control,
     .keys = kControl,
     .title = "Movement and the control loop",
     .help = "How the controller moves the antenna ([control.md](control.md))."},
    {.name = "geometry",
     .chapter = Chapter::Control,
     .keys = kGeometry,
     .title = "The travel",
     .help = "The mount's travel in its own degrees."},
    {.name = "corrections",
     .chapter = Chapter::Control,
     .keys = kCorrections,
     .title = "Position corrections",
     .help = "Applied to every reading, in this order: the encoder offsets, the pointing model, "
             "the operator's corrections and the tilt table ([control.md](control.md))."},
    {.name = "pointing",
     .chapter = Chapter::Control,
     .keys = kPointing,
     .title = "The pointing model",
     .help = "The fitted pointing model, applied to every reading after the encoder offset "
             "([calibration.md](calibration.md))."},
    {.name = "park",
     .chapter = Chapter::Control,
     .array_of_tables = true,
     .keys = kPark,
     .title = "Park slots",
     .help = "Up to four slots, in order; without them: `park` 180/el_min, `stow` 180/el_max (at "
             "most 90), `north` 0/el_min, `service` 90/el_min. rotctld `K`, EasyComm `PARK`, "
             "PstRotator `<PARK>` and `out_of_range = \"park\"` use slot 1."},
    {.name = "mount", .chapter = Chapter::Control, .title = "The mount"},
    {.name = "mount.az",
     .chapter = Chapter::Control,
     .keys = kMountAz,
     .title = "The mount's azimuth axis",
     .help = "What the controller knows of the real axis, whatever drives it; the simulated "
             "plant turns at this rate and reads these encoders."},
    {.name = "mount.el",
     .chapter = Chapter::Control,
     .keys = kMountEl,
     .title = "The mount's elevation axis",
     .help = "As `[mount.az]`, for the elevation axis; or, with `fixed_deg`, an elevation that "
             "does not move."},
    {.name = "mount.pol",
     .chapter = Chapter::Control,
     .keys = kMountPol,
     .title = "The mount's polarisation axis",
     .help = "A feed or array rotator ([eme.md](eme.md)); without this table the station has "
             "no pol axis. As `[mount.az]`, with its travel and window."},
    {.name = "pol",
     .chapter = Chapter::Control,
     .keys = kPol,
     .title = "What the polarisation axis follows",
     .help = "The modes of [eme.md](eme.md)'s polarisation axis; the DX station is `[sky] "
             "dx_grid`."},
}};

}  // namespace

std::span<const SectionSpec> control_sections() { return kSections; }

}  // namespace azt::app
