// The schema's radio keys: the rig kept on frequency through rigctld or libhamlib, the
// satellites' transmitters, and WSJT-X's UDP messages (radio_config.cpp and wsjtx_config.cpp read
// them; docs/radio.md).
#include <array>

#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<std::string_view, 3> kDoppler{"off", "satellite", "eme"};
constexpr std::array<std::string_view, 5> kEmeModes{"dx", "self", "constant", "on_dx", "call_dx"};
constexpr std::array<std::string_view, 3> kTransponders{"fm", "linear", "linear_inverting"};

constexpr std::array<KeySpec, 13> kRadio{{
    {.key = "rigctld",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "the rig through Hamlib's rigctld: `\"HOST:PORT\"` (rigctld's port is 4532); "
             "empty: no rig, or the rig is `model`"},
    {.key = "model",
     .type = KeyType::Integer,
     .range = closed(0.0, 100000.0),
     .default_toml = "0",
     .help = "or the rig through libhamlib directly: its Hamlib model number (`rigctl -l`: 1 "
             "the dummy, 3073 IC-7300, 3081 IC-9700, 1020 FT-817, …); 0: none. Not with "
             "`rigctld`; checked against Hamlib's list when the file is loaded "
             "([radio.md](radio.md#through-rigctld-or-directly))"},
    {.key = "device",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "with `model`: the rig's CAT port, a serial device (`/dev/ttyUSB0`, better "
             "`/dev/serial/by-id/…`); empty: the model's default"},
    {.key = "baud",
     .type = KeyType::Integer,
     .range = closed(0.0, 1000000.0),
     .default_toml = "0",
     .help = "with `model`: the serial speed (as set on the rig); 0: the model's default"},
    {.key = "tx_rigctld",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "a second rig for the uplink (`\"HOST:PORT\"`); empty: the uplink goes to the "
             "rig's split VFO (or to `tx_model`)"},
    {.key = "tx_model",
     .type = KeyType::Integer,
     .range = closed(0.0, 100000.0),
     .default_toml = "0",
     .help = "or the uplink's rig through libhamlib directly, as `model`; 0: none. Not with "
             "`tx_rigctld`"},
    {.key = "tx_device",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "with `tx_model`: the uplink rig's CAT port (not `device`)"},
    {.key = "tx_baud",
     .type = KeyType::Integer,
     .range = closed(0.0, 1000000.0),
     .default_toml = "0",
     .help = "with `tx_model`: its serial speed; 0: the model's default"},
    {.key = "doppler",
     .type = KeyType::Choice,
     .choices = kDoppler,
     .default_toml = "\"off\"",
     .help = "who azeltrack keeps on frequency: `off` (writes nothing: WSJT-X or Gpredict may "
             "own the rig), the tracked `satellite`'s transmitter, or the Moon's `eme` echo"},
    {.key = "eme_mode",
     .type = KeyType::Choice,
     .choices = kEmeModes,
     .default_toml = "\"dx\"",
     .help = "WSJT-X's EME Doppler mode ([radio.md](radio.md)): full `dx`, own echo `self`, "
             "`constant` frequency on the Moon, `on_dx` echo, `call_dx`"},
    {.key = "dial_mhz",
     .type = KeyType::Number,
     .unit = "MHz",
     .range = closed(0.0, 1e6),
     .default_toml = "0.0",
     .help = "EME: the nominal dial frequency the corrections are added to"},
    {.key = "step_hz",
     .type = KeyType::Number,
     .unit = "Hz",
     .range = closed(1.0, 10000.0),
     .default_toml = "10.0",
     .help = "satellites: a leg is written when it moved this much (quoted at 435 MHz, scaled "
             "with the frequency), or 1 Hz after a second"},
    {.key = "no_tx_qsy",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the rig cannot change frequency while transmitting: EME's TX correction is set "
             "once per T/R period, before keying"},
}};

constexpr std::array<KeySpec, 4> kTransmitter{{
    {.key = "norad",
     .type = KeyType::Text,
     .default_note = "required",
     .help = "the satellite's NORAD catalogue number, as its element set gives it"},
    {.key = "downlink_mhz",
     .type = KeyType::Number,
     .unit = "MHz",
     .range = above(0.0),
     .default_note = "required",
     .help = "the downlink (satellite frame); for a transponder, a point of its passband"},
    {.key = "uplink_mhz",
     .type = KeyType::Number,
     .unit = "MHz",
     .range = closed(0.0, 1e6),
     .default_toml = "0.0",
     .help = "the uplink that comes down at `downlink_mhz`; 0: receive only"},
    {.key = "mode",
     .type = KeyType::Choice,
     .choices = kTransponders,
     .default_toml = "\"fm\"",
     .help = "`fm` (a channel), or a `linear` / `linear_inverting` transponder whose passband "
             "the rig's dial tunes across"},
}};

constexpr std::array<KeySpec, 4> kWsjtx{{
    {.key = "listen",
     .type = KeyType::Text,
     .default_toml = "\"\"",
     .help = "where WSJT-X's UDP messages arrive (its UDP Server setting), `\"127.0.0.1:2237\"`; "
             "a multicast group address joins the group; empty: not listening"},
    {.key = "follow_dx_grid",
     .type = KeyType::Boolean,
     .default_toml = "true",
     .help = "WSJT-X's DX grid becomes the running DX locator (not saved)"},
    {.key = "hold_motion_while_transmitting",
     .type = KeyType::Boolean,
     .default_toml = "true",
     .help = "no antenna motion while WSJT-X says it transmits, as with the PTT input"},
    {.key = "move_in_last_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.0, 1800.0),
     .default_toml = "0.0",
     .help = "move only in the last seconds of each T/R period; 0: whenever not transmitting"},
}};

constexpr std::array<SectionSpec, 3> kSections{{
    {.name = "radio",
     .chapter = Chapter::Radio,
     .keys = kRadio,
     .title = "The rig",
     .help = "Doppler to the rig over Hamlib's rigctld or libhamlib directly "
             "([radio.md](radio.md))."},
    {.name = "satellites.transmitter",
     .chapter = Chapter::Radio,
     .array_of_tables = true,
     .keys = kTransmitter,
     .title = "Satellite transmitters",
     .help = "The frequencies the rig follows while that satellite is tracked, one table each."},
    {.name = "wsjtx",
     .chapter = Chapter::Radio,
     .keys = kWsjtx,
     .title = "WSJT-X",
     .help = "WSJT-X's UDP messages: its DX grid and its transmitting."},
}};

}  // namespace

std::span<const SectionSpec> radio_sections() { return kSections; }

}  // namespace azt::app
