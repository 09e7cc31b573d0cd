// The schema's station I/O keys: the E-stop, limit switches, PTT and buttons on GPIO lines, the T/R
// sequencer (daemon_config.cpp reads them) and a game pad (gamepad_config.cpp).
#include <array>

#include "azt/sequencer/tr_sequencer.hpp"
#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

/// A line that may be absent (not wired).
constexpr KeySpec line(std::string_view key, std::string_view help) {
  return {.key = key, .type = KeyType::GpioLine, .default_note = "none", .help = help};
}

constexpr KeySpec active_low(std::string_view key, std::string_view default_toml,
                             std::string_view help) {
  return {.key = key, .type = KeyType::Boolean, .default_toml = default_toml, .help = help};
}

constexpr std::array<KeySpec, 25> kGpio{{
    {.key = "chip",
     .type = KeyType::Text,
     .default_toml = "\"gpiochip0\"",
     .help = "the GPIO chip of lines given as numbers (0 to 1023); any line may be `\"CHIP:N\"` "
             "instead. Each line may be used once, the relays of `[hardware.*]` included"},
    line("estop",
         "the E-stop input (a normally closed button to ground with the pull-up: open = stop), "
         "latched in `estop_latch_file` across restarts until faults are cleared with the button "
         "released"),
    active_low("estop_active_low", "false", "the E-stop line reads pressed when low"),
    line("az_ccw_limit",
         "the counter-clockwise travel-end switch (normally closed to ground: a cut wire reads "
         "tripped); the drive towards a tripped switch goes off on the edge"),
    line("az_cw_limit", "the clockwise travel-end switch"),
    line("el_down_limit", "the lower elevation travel-end switch"),
    line("el_up_limit", "the upper elevation travel-end switch"),
    line("pol_ccw_limit",
         "the polarisation axis's travel-end switch at its counter-clockwise end (`[mount.pol]` "
         "min_deg); needs `[mount.pol]`"),
    line("pol_cw_limit", "the polarisation axis's switch at its clockwise end (max_deg)"),
    active_low("limits_active_low", "false", "the limit lines read tripped when low"),
    line("ptt", "the PTT input keying the `[sequencer]` chain; needs `[gpio] sequencer`"),
    active_low("ptt_active_low", "true", "the radio's PTT output pulls its line low"),
    {.key = "sequencer",
     .type = KeyType::IntegerList,
     .range = closed(0.0, 1023.0),
     .items = {0, 8},
     .default_note = "none",
     .help = "one output line per `[sequencer] outputs` name, in keying order; de-energized is "
             "receive"},
    active_low("sequencer_active_low", "false", "the sequencer's outputs energise low"),
    {.key = "estop_latch_file",
     .type = KeyType::Text,
     .default_note = "estop.latched beside the configuration",
     .help = "where a latched E-stop is remembered across restarts"},
    line("button_cw",
         "the clockwise button at the mast: the antenna turns while it is held, through the same "
         "front door as every other source (the console shows the source \"buttons\")"),
    line("button_ccw", "the counter-clockwise button"),
    line("button_up", "the UP button"),
    line("button_down", "the DOWN button"),
    line("button_stop",
         "the STOP button: stops the antenna and locks PC programs out as the console's STOP "
         "does (not an E-stop: that is `estop`)"),
    line("button_park", "the PARK button: parks in slot `button_park_slot`"),
    active_low("buttons_active_low", "true", "the buttons pull their lines low when pressed"),
    {.key = "button_debounce_ms",
     .type = KeyType::Number,
     .range = closed(0.0, 500.0),
     .default_toml = "30",
     .help = "how long a button's new level must hold before it counts (contact bounce)"},
    {.key = "button_speed",
     .type = KeyType::Number,
     .range = closed(0.05, 1.0),
     .default_toml = "1.0",
     .help = "a jog button's speed, a fraction of the axis's full rate"},
    {.key = "button_park_slot",
     .type = KeyType::Integer,
     .range = closed(1.0, 4.0),
     .default_toml = "1",
     .help = "the `[[park]]` slot the PARK button parks in"},
}};

static_assert(sequencer::SequencerConfig::kMaxOutputs == 8, "[sequencer] outputs' count");
static_assert(sequencer::SequencerConfig::kMaxDelayMs == 2000.0, "[sequencer] delays' range");

constexpr std::array<KeySpec, 6> kSequencer{{
    {.key = "outputs",
     .type = KeyType::TextList,
     .items = {1, 8},
     .default_toml = R"(["preamp", "trx_relay", "amplifier", "radio"])",
     .help = "the T/R chain in keying order, different names"},
    {.key = "delay_ms",
     .type = KeyType::Number,
     .unit = "ms",
     .range = closed(1.0, 2000.0),
     .default_toml = "20.0",
     .help = "the delay between steps; give this or `delays_ms`, not both"},
    {.key = "delays_ms",
     .type = KeyType::NumberList,
     .unit = "ms",
     .range = closed(1.0, 2000.0),
     .items = {0, 7},
     .default_note = "delay_ms each",
     .help = "one delay per gap between outputs"},
    {.key = "debounce_ms",
     .type = KeyType::Number,
     .unit = "ms",
     .range = closed(0.0, 200.0),
     .default_toml = "10.0",
     .help = "PTT debounce"},
    {.key = "tx_timeout_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(1.0, 3600.0),
     .default_toml = "600.0",
     .help = "transmit time-out (always on)"},
    {.key = "hold_motion",
     .type = KeyType::Boolean,
     .default_toml = "true",
     .help = "no antenna motion while keyed"},
}};

constexpr std::array<KeySpec, 4> kGamepad{{
    {.key = "device",
     .type = KeyType::Text,
     .default_note = "none",
     .help = "the game pad's input node, best its `/dev/input/by-id/…-event-joystick` link; looked "
             "for again every 2 s while absent (docs/hardware.md)"},
    {.key = "dead_zone",
     .type = KeyType::Number,
     .range = closed(0.0, 0.9),
     .default_toml = "0.15",
     .help = "the stick's dead zone, a fraction of its half range beyond the driver's flat zone"},
    {.key = "speed",
     .type = KeyType::Number,
     .range = closed(0.05, 1.0),
     .default_toml = "1.0",
     .help = "the speed at full deflection and the D-pad's, a fraction of the axis's full rate"},
    {.key = "park_slot",
     .type = KeyType::Integer,
     .range = closed(1.0, 4.0),
     .default_toml = "1",
     .help = "the `[[park]]` slot START parks in"},
}};

constexpr std::array<SectionSpec, 3> kSections{{
    {.name = "gpio",
     .chapter = Chapter::StationIo,
     .keys = kGpio,
     .title = "E-stop, limit switches and PTT",
     .help = "The station's GPIO lines; wiring in [hardware.md](hardware.md)."},
    {.name = "sequencer",
     .chapter = Chapter::StationIo,
     .keys = kSequencer,
     .title = "The T/R sequencer",
     .help = "How it behaves: [command-line.md](command-line.md) (`seq-sim`); wiring: "
             "[hardware.md](hardware.md)."},
    {.name = "gamepad",
     .chapter = Chapter::StationIo,
     .keys = kGamepad,
     .title = "A game pad at the mast",
     .help =
         "A USB game pad or joystick steering the antenna: the left stick or the D-pad moves, A "
         "(✕) stops, START parks; wiring and rules in [hardware.md](hardware.md)."},
}};

}  // namespace

std::span<const SectionSpec> station_io_sections() { return kSections; }

}  // namespace azt::app
