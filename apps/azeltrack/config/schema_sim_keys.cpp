// The schema's keys of the simulated antenna: its hub link, its plants, how its beam really points
// and its receiver (sim_config.cpp and pointing_config.cpp read them).
#include <array>

#include "config/schema_keys.hpp"
#include "config/schema_motor_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<std::string_view, 2> kFrameVersions{"seed", "crc8"};
constexpr std::array<std::string_view, 2> kHubKinds{"model", "firmware"};

constexpr std::array<KeySpec, 6> kSim{{
    {.key = "frame_version",
     .type = KeyType::Choice,
     .choices = kFrameVersions,
     .default_toml = "\"crc8\"",
     .help = "the simulated EncoderHub's frames: `seed` (AnTrack-Pro) or `crc8`"},
    {.key = "frame_loss",
     .type = KeyType::Number,
     .range = closed(0.0, 1.0),
     .default_toml = "0.0",
     .help = "probability of a lost frame"},
    {.key = "byte_corruption",
     .type = KeyType::Number,
     .range = closed(0.0, 1.0),
     .default_toml = "0.0",
     .help = "probability of a corrupted byte"},
    {.key = "seed",
     .type = KeyType::Integer,
     .default_toml = "1",
     .help = "random seed of the link faults"},
    {.key = "hub",
     .type = KeyType::Choice,
     .choices = kHubKinds,
     .default_toml = "\"model\"",
     .help = "`firmware`: the simulated encoders are read by the EncoderHub firmware running on a "
             "simulated ATmega328P, its frames through the daemon's decoder, in `serve` and in "
             "`simulate` ([encoder-hub.md](encoder-hub.md))"},
    {.key = "hub_firmware",
     .type = KeyType::Text,
     .default_note = "beside the program",
     .help = "the firmware's ELF: by default `firmware/encoder-hub.elf` beside the program, "
             "`build/firmware/encoder-hub.elf` in the build tree, else the package's "
             "`/usr/share/azeltrack/firmware/encoder-hub.elf`"},
}};

constexpr std::array<std::string_view, 3> kFaults{"frozen_shaft", "reversed_motor",
                                                  "encoder_offset"};

constexpr std::array<KeySpec, 22> kPlant{{
    {.key = "time_constant_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = above(0.0),
     .default_note = "the mount's",
     .help = "the simulated motor's speed response (default: what the controller is told)"},
    {.key = "backlash_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = at_least(0.0),
     .default_note = "the mount's",
     .help = "the simulated gear play"},
    {.key = "stiction_duty",
     .type = KeyType::Number,
     .range = from_below(0.0, 1.0),
     .default_note = "the mount's min_duty",
     .help = "drive at or below which the simulated motor does not turn"},
    {.key = "start_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_note = "0, within the stops",
     .help = "where the simulated axis starts, within its stops (a real station believes it "
             "starts at 0°, or the nearest end of its travel, until the first reading)"},
    {.key = "min_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_note = "the travel's",
     .help = "the simulated axis's lower end stop"},
    {.key = "max_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_note = "the travel's",
     .help = "the simulated axis's upper end stop"},
    {.key = "fault",
     .type = KeyType::Choice,
     .choices = kFaults,
     .default_note = "none",
     .help = "a plant fault to rehearse from `fault_at_s` after the start: `frozen_shaft` (the "
             "stall supervisor latches), `reversed_motor`, `encoder_offset` (by `fault_counts`)"},
    {.key = "fault_at_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = at_least(0.0),
     .default_toml = "0.0",
     .help = "seconds after the start"},
    {.key = "fault_counts",
     .type = KeyType::Integer,
     .range = closed(-65535.0, 65535.0),
     .default_toml = "100",
     .help = "the encoder offset's counts"},
    {.key = "brake",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "a spring-applied brake that holds the simulated shaft until its line has been on "
             "for `brake_lift_s`; the station drives its line with the `brake_release_s`, "
             "`brake_engage_s` and `brake_idle_s` of a real axis ([hardware.md](hardware.md))"},
    number_key("brake_lift_s", "s", above_up_to(0.0, 60.0), "1.2",
               "the simulated brake's own lift time, from its line on to the shaft free (above "
               "`brake_release_s`, the motor pulls against it)"),
    number_key("brake_hold_s", "s", above_up_to(0.0, 60.0), "0.3",
               "the simulated brake's time from its line off to holding fully"),
    kBrakeReleaseKey,
    kBrakeEngageKey,
    kBrakeIdleKey,
    {.key = "motor_heating",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the simulated motor's winding heats with the square of its duty and cools towards "
             "`ambient_c`; the station reads it as a temperature sensor on the motor and trips "
             "the axis above `temperature_limit_c`"},
    number_key("motor_rise_c", "°C", closed(0.0, 500.0), "80.0",
               "the winding's steady rise above ambient_c at full duty"),
    number_key("motor_time_constant_s", "s", above_up_to(0.0, 36000.0), "300.0",
               "how fast the winding heats and cools"),
    number_key("ambient_c", "°C", closed(-50.0, 60.0), "20.0", "the air around the motor"),
    {.key = "motor_start_c",
     .type = KeyType::Number,
     .unit = "°C",
     .range = closed(-50.0, 200.0),
     .default_note = "ambient_c",
     .help = "the winding's temperature at the start (a motor still warm from a long move)"},
    {.key = "temperature_limit_c",
     .type = KeyType::Number,
     .unit = "°C",
     .range = closed(0.0, 200.0),
     .default_note = "none: required with motor_heating",
     .help = "the axis trips above this winding temperature, as `[hardware.az]`'s"},
    kTemperatureHysteresisKey,
}};

constexpr KeySpec mount_error(std::string_view key, std::string_view help) {
  return {.key = key,
          .type = KeyType::Number,
          .unit = "°",
          .range = within(10.0),
          .default_toml = "0.0",
          .help = help};
}

constexpr std::array<KeySpec, 7> kMountErrors{{
    mount_error("az_offset_deg", "azimuth encoder zero (the model's IA)"),
    mount_error("el_offset_deg", "elevation encoder zero (IE)"),
    mount_error("collimation_deg", "collimation (CA)"),
    mount_error("nonperp_deg", "axes' non-perpendicularity (NPAE)"),
    mount_error("az_tilt_deg", "azimuth axis tilt, towards `az_tilt_toward_deg`"),
    {.key = "az_tilt_toward_deg",
     .type = KeyType::Number,
     .unit = "°",
     .default_toml = "0.0",
     .help = "the azimuth the axis tilts towards"},
    mount_error("el_sag_deg", "elevation sag (SAG)"),
}};

constexpr std::array<std::string_view, 3> kFluxBands{"1296", "2304", "10368"};

constexpr std::array<KeySpec, 10> kSimReceiver{{
    number_key("beamwidth_deg", "°", above_up_to(0.0, 30.0), "1.6", "half-power beamwidth"),
    number_key("tsys_k", "K", above_up_to(0.0, 1e5), "50.0", "system noise on cold sky"),
    number_key("noise_db", "dB", closed(0.0, 10.0), "0.1", "rms of one reading"),
    number_key("rate_hz", "Hz", above_up_to(0.0, 100.0), "5.0", "readings per second"),
    number_key("dish_m", "m", above_up_to(0.0, 100.0), "10.0",
               "dish diameter, for the radio sources' antenna temperatures"),
    number_key("efficiency", "", above_up_to(0.0, 1.0), "0.6", "aperture efficiency"),
    number_key("sun_k", "K", above_up_to(0.0, 1e8), "170000.0", "the Sun's temperature"),
    number_key("moon_k", "K", above_up_to(0.0, 1e4), "220.0", "the Moon's temperature"),
    {.key = "flux_mhz",
     .type = KeyType::Integer,
     .unit = "MHz",
     .choices = kFluxBands,
     .default_toml = "1296",
     .help = "the frequency of the catalogue's flux densities used"},
    {.key = "seed",
     .type = KeyType::Integer,
     .default_toml = "1",
     .help = "random seed of the noise"},
}};

/// [sim.pol]: the plant's own keys without the scheduled faults (none for the pol plant yet).
constexpr std::array<KeySpec, 6> kPolPlant{
    {kPlant[0], kPlant[1], kPlant[2], kPlant[3], kPlant[4], kPlant[5]}};

/// [sim.el] alone: the dish of an elevation on a linear actuator ([hardware.el] sensor = "pulses"
/// with counts_per_mm, or a pot with pot_calibration_mm; the actuator's triangle), flown as a
/// linear actuator (sim_actuator_config.cpp).
constexpr std::array<KeySpec, 2> kActuatorPlant{{
    {.key = "actuator_speed_mm_s",
     .type = KeyType::Number,
     .unit = "mm/s",
     .range = above_up_to(0.0, 200.0),
     .default_toml = "8.0",
     .help = "an actuator elevation's speed at full duty, read by its pulses or its pot (a 36 V "
             "superjack: about 8)"},
    {.key = "drop_pulse_at_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.0, 1.0e6),
     .default_note = "none",
     .help = "the first reed pulse from this simulated time on is lost: the next pass of the home "
             "switch must find the count off by one (refused with a pot)"},
}};

/// `a`'s keys, then `b`'s.
template <std::size_t A, std::size_t B>
constexpr std::array<KeySpec, A + B> joined(const std::array<KeySpec, A>& a,
                                            const std::array<KeySpec, B>& b) {
  std::array<KeySpec, A + B> out{};
  for (std::size_t i = 0; i < A; ++i) out.at(i) = a.at(i);
  for (std::size_t i = 0; i < B; ++i) out.at(A + i) = b.at(i);
  return out;
}
constexpr auto kElPlant = joined(kPlant, kActuatorPlant);

constexpr std::array<SectionSpec, 6> kSections{{
    {.name = "sim",
     .chapter = Chapter::Simulation,
     .keys = kSim,
     .title = "The simulated EncoderHub link",
     .help = "Used by the `sim` backend and by `azeltrack simulate` ([control.md](control.md))."},
    {.name = "sim.az",
     .chapter = Chapter::Simulation,
     .keys = kPlant,
     .title = "The simulated azimuth axis",
     .help = "The plant turns at the mount's rate and reads the mount's encoders "
             "(`[mount.az]`); these are its own. With `brake` or `motor_heating` the plant also "
             "has a brake or a winding that heats, and the station drives and watches them as "
             "a real axis's ([hardware.md](hardware.md) \"Brake, current and temperature\")."},
    {.name = "sim.el",
     .chapter = Chapter::Simulation,
     .keys = kElPlant,
     .title = "The simulated elevation axis",
     .help =
         "As `[sim.az]`, for the elevation axis; with `[hardware.el] sensor = \"pulses\"` "
         "and `counts_per_mm`, a dish on a linear actuator counted by a reed from a home switch, "
         "or with a pot on an ADC (`sensor = \"mcp3008\"` or `\"ads1115\"`) and "
         "`pot_calibration_mm`, the same dish read by its feedback pot "
         "([hardware.md](hardware.md) \"Linear actuators\")."},
    {.name = "sim.pol",
     .chapter = Chapter::Simulation,
     .keys = kPolPlant,
     .title = "The simulated polarisation axis",
     .help = "With `[mount.pol]`: the plant of the feed rotator, its encoder read each tick; as "
             "`[sim.az]` without the faults, the brake and the heating."},
    {.name = "sim.mount_errors",
     .chapter = Chapter::Simulation,
     .keys = kMountErrors,
     .title = "How the simulated beam really points",
     .help = "The terms of the pointing model, as the simulated mount has them "
             "([calibration.md](calibration.md))."},
    {.name = "sim.receiver",
     .chapter = Chapter::Simulation,
     .keys = kSimReceiver,
     .title = "The simulated receiver of scans",
     .help = "By default a 10 m dish at 23 cm."},
}};

}  // namespace

std::span<const SectionSpec> sim_sections() { return kSections; }

}  // namespace azt::app
