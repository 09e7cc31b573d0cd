// The schema's antenna keys: the backend and what it drives, a Hamlib box, the EncoderHub and the
// PWM bridges (daemon_config.cpp reads them; the per-axis hardware is schema_hardware_keys.cpp).
#include <array>

#include "config/daemon_config.hpp"
#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr auto kBackendNames = choice_names(kBackendKinds);

constexpr std::array<KeySpec, 1> kAntenna{{
    {.key = "backend",
     .type = KeyType::Choice,
     .choices = kBackendNames,
     .default_toml = "\"sim\"",
     .help = "`sim`: the simulated antenna; `hamlib`: an existing controller through Hamlib "
             "(needs a `[hamlib]` table; [daemon.md](daemon.md#the-hamlib-backend)); `pwm`: "
             "EncoderHub and IBT-2 bridges on both axes (needs `[hub] device`); `hardware`: drive "
             "and sensor chosen per axis in `[hardware.az]` / `[hardware.el]` "
             "([hardware.md](hardware.md))"},
}};

constexpr std::array<KeySpec, 5> kHamlib{{
    {.key = "model",
     .type = KeyType::Integer,
     .range = closed(1.0, 100000.0),
     .default_toml = "1",
     .help = "Hamlib rotator model (`rotctl -l`): 601 GS-232A, 603 GS-232B, 202 EasyComm II, 901 "
             "SPID Rot2Prog, 2 another rotctld, 1 dummy"},
    {.key = "device",
     .type = KeyType::Text,
     .default_note = "Hamlib's",
     .help = "serial device, or `host:port` for model 2"},
    {.key = "baud",
     .type = KeyType::Integer,
     .range = closed(0.0, 1000000.0),
     .default_toml = "0",
     .help = "serial speed; 0 keeps the model's default (and must be 0 for network models)"},
    {.key = "poll_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.05, 5.0),
     .default_toml = "0.2",
     .help = "position read-back period"},
    {.key = "min_move_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(0.0, 10.0),
     .default_toml = "0.1",
     .help = "a setpoint within this of the last one sent on both axes is not resent"},
}};

constexpr std::array<std::string_view, 2> kHubAccept{"crc8", "seed"};

constexpr std::array<KeySpec, 3> kHub{{
    {.key = "device",
     .type = KeyType::Text,
     .help = "the EncoderHub's serial device (needed by the `pwm` backend, and by `hardware` with "
             "a `hub` sensor)"},
    {.key = "baud",
     .type = KeyType::Integer,
     .range = closed(600.0, 115200.0),
     .default_toml = "38400",
     .help = "38400 is azeltrack's hub firmware without a baud jumper "
             "([encoder-hub.md](encoder-hub.md))"},
    {.key = "accept",
     .type = KeyType::Choice,
     .choices = kHubAccept,
     .default_toml = "\"crc8\"",
     .help = "the frames accepted: `crc8` (azeltrack's hub) or `seed` (AnTrack-Pro frames)"},
}};

constexpr KeySpec pwm_channel(std::string_view key, std::string_view default_toml,
                              std::string_view help) {
  return {.key = key,
          .type = KeyType::Integer,
          .range = closed(0.0, 63.0),
          .default_toml = default_toml,
          .help = help};
}

constexpr std::array<KeySpec, 9> kPwm{{
    {.key = "chip",
     .type = KeyType::Text,
     .default_toml = "\"/sys/class/pwm/pwmchip0\"",
     .help = "the sysfs PWM chip of every bridge"},
    pwm_channel("az_rpwm", "0", "the azimuth bridge's RPWM channel; the channels all differ"),
    pwm_channel("az_lpwm", "1", "the azimuth bridge's LPWM channel"),
    pwm_channel("el_rpwm", "2", "the elevation bridge's RPWM channel"),
    pwm_channel("el_lpwm", "3", "the elevation bridge's LPWM channel"),
    pwm_channel("pol_rpwm", "4",
                "the polarisation bridge's RPWM channel (`[hardware.pol]` drive = \"pwm\")"),
    pwm_channel("pol_lpwm", "5", "the polarisation bridge's LPWM channel"),
    {.key = "frequency_hz",
     .type = KeyType::Number,
     .unit = "Hz",
     .range = closed(10.0, 100000.0),
     .default_toml = "1000.0",
     .help = "PWM frequency"},
    {.key = "dead_time_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.01, 3.0),
     .default_toml = "0.1",
     .help = "both PWMs at zero this long before a reversal"},
}};

constexpr std::array<SectionSpec, 4> kSections{{
    {.name = "antenna",
     .chapter = Chapter::Antenna,
     .keys = kAntenna,
     .title = "The antenna behind the station"},
    {.name = "hamlib",
     .chapter = Chapter::Antenna,
     .keys = kHamlib,
     .title = "A rotator controller through Hamlib",
     .help = "For `[antenna] backend = \"hamlib\"`."},
    {.name = "hub",
     .chapter = Chapter::Antenna,
     .keys = kHub,
     .title = "The EncoderHub",
     .help = "The encoders' serial link ([encoder-hub.md](encoder-hub.md))."},
    {.name = "pwm",
     .chapter = Chapter::Antenna,
     .keys = kPwm,
     .title = "Two IBT-2 bridges",
     .help = "The bridges of the `pwm` backend, and of a `hardware` axis with `drive = \"pwm\"`."},
}};

}  // namespace

std::span<const SectionSpec> antenna_sections() { return kSections; }

}  // namespace azt::app
