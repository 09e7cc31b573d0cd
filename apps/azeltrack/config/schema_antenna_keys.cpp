// The schema's antenna keys: the backend and what it drives, a Hamlib box, the EncoderHub, the
// PWM bridges and the per-axis hardware (daemon_config.cpp and hardware_config.cpp read them).
#include <array>

#include "config/daemon_config.hpp"
#include "config/hardware_config.hpp"
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

constexpr auto kDriveNames = choice_names(kAxisDriveKinds);
constexpr auto kSensorNames = choice_names(kAxisSensorKinds);

/// A relay-drive line: a GPIO line on [gpio] chip, or "CHIP:N".
constexpr KeySpec relay_line(std::string_view key, std::string_view help) {
  return {.key = key, .type = KeyType::GpioLine, .default_note = "none", .help = help};
}

constexpr std::array<KeySpec, 3> kMotorPower{{
    {.key = "relay",
     .type = KeyType::GpioLine,
     .default_note = "none: the motors are always powered",
     .help = "the relay that switches the motors' supply, active = powered; `\"sim:N\"` is a "
             "simulated line of the `sim` backend, shown in /api/state"},
    {.key = "active_low",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the relay board switches on a low level"},
    {.key = "on_lead_s",
     .type = KeyType::Number,
     .unit = "s",
     .range = closed(0.0, 120.0),
     .default_toml = "5.0",
     .help = "after switching on, motion waits this long (the supply and the drives settle)"},
}};

constexpr KeySpec relay_number(std::string_view key, std::string_view unit, Range range,
                               std::string_view default_toml, std::string_view help) {
  return {.key = key,
          .type = KeyType::Number,
          .unit = unit,
          .range = range,
          .default_toml = default_toml,
          .help = help};
}

constexpr std::array<KeySpec, 49> kHardwareAxis{{
    {.key = "drive",
     .type = KeyType::Choice,
     .choices = kDriveNames,
     .default_toml = "\"pwm\"",
     .help = "`pwm`: an IBT-2 on the `[pwm]` channels; `relay`: GPIO relays (the `relay_*` keys); "
             "`pot`: an MCP41010 in the rotator box (`spi_device`, `wiper_calibration`); "
             "`stepdir`: a stepper's step/direction driver (`step_channel`, `dir`, the `*step*` "
             "keys)"},
    {.key = "sensor",
     .type = KeyType::Choice,
     .choices = kSensorNames,
     .default_toml = "\"hub\"",
     .help = "`hub`: this axis of the EncoderHub on `[hub]`; `mcp3008` (spidev, 10 bits of 3.3 V) "
             "or `ads1115` (i2c-dev, ±4.096 V, 15 bits): a pot read by an ADC (the `adc_*` keys "
             "and `pot_calibration`)"},
    {.key = "enable",
     .type = KeyType::GpioLine,
     .default_note = "tied high",
     .help = "`drive = \"pwm\"`: the IBT-2's R_EN/L_EN on a GPIO line; `drive = \"stepdir\"`: "
             "the driver's ENABLE (off on a stop or fault: no holding torque)"},
    {.key = "step_chip",
     .type = KeyType::Text,
     .default_toml = "\"/sys/class/pwm/pwmchip0\"",
     .help = "`drive = \"stepdir\"`: the sysfs PWM chip of STEP"},
    {.key = "step_channel",
     .type = KeyType::Integer,
     .range = closed(0.0, 15.0),
     .default_note = "none",
     .help = "`drive = \"stepdir\"`, required: the PWM channel wired to STEP (its frequency is "
             "the step rate)"},
    relay_line("dir", "`drive = \"stepdir\"`, required: the driver's DIR, active = clockwise / up"),
    relay_number("max_step_hz", "Hz", closed(1.0, 100000.0), "2000.0",
                 "`drive = \"stepdir\"`: the step rate at full speed, `[mount.*]` rate × steps "
                 "per degree"),
    relay_number("start_step_hz", "Hz", closed(0.0, 100000.0), "200.0",
                 "the stepper's pull-in rate: started and stopped at without a ramp"),
    relay_number("step_accel_hz_s", "Hz/s", closed(1.0, 1000000.0), "4000.0",
                 "the largest change of step rate per second above the pull-in rate"),
    relay_line("relay_forward",
               "`drive = \"relay\"`: the clockwise / up relay, with relay_reverse"),
    relay_line("relay_reverse", "the counter-clockwise / down relay, with relay_forward"),
    relay_line("relay_power", "or: the motor's power relay, with relay_polarity"),
    relay_line("relay_polarity", "the polarity relay that chooses the direction, with relay_power"),
    {.key = "relay_active_low",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the relay lines energise their relays low"},
    relay_number("window_deg", "°", closed(0.0, 10.0), "1.0", "the relay drive's movement window"),
    relay_number("lsb_deg", "°", above_up_to(0.0, 1.0), "0.3515625",
                 "one step of the position reading (360/1024)"),
    relay_number("coast_deg", "°", closed(0.0, 10.0), "0.0",
                 "how far the axis runs on after its relay opens at full speed"),
    relay_number("min_on_s", "s", closed(0.0, 10.0), "0.1",
                 "an energised relay stays on at least this long"),
    relay_number("reversal_dead_s", "s", above_up_to(0.0, 60.0), "0.5",
                 "after a release, both directions stay off this long before a reversal"),
    relay_number("polarity_settle_s", "s", closed(0.0, 1.0), "0.05",
                 "the polarity relay settles this long before the power relay closes"),
    {.key = "spi_device",
     .type = KeyType::Text,
     .help = "`drive = \"pot\"`, required: the MCP41010's spidev (`/dev/spidevB.C`)"},
    {.key = "spi_hz",
     .type = KeyType::Integer,
     .unit = "Hz",
     .range = closed(10000.0, 10000000.0),
     .default_toml = "1000000",
     .help = "the MCP41010's SPI clock"},
    {.key = "wiper_calibration",
     .type = KeyType::NumberList,
     .items = {4, 4},
     .help = "`drive = \"pot\"`, required: `[wiper_a, deg_a, wiper_b, deg_b]`, two wiper codes "
             "(0 to 255) and the angles they set"},
    relay_number("setpoint_band_deg", "°", above_up_to(0.0, 20.0), "2.0",
                 "the rotator box's own dead band around a setpoint"),
    {.key = "adc_device",
     .type = KeyType::Text,
     .help = "an ADC sensor, required: `/dev/spidevB.C` (MCP3008) or `/dev/i2c-N` (ADS1115)"},
    {.key = "adc_channel",
     .type = KeyType::Integer,
     .range = closed(0.0, 7.0),
     .default_toml = "0",
     .help = "the ADC's input: 0 to 7 on the MCP3008, 0 to 3 on the ADS1115"},
    {.key = "adc_address",
     .type = KeyType::Integer,
     .range = closed(72.0, 75.0),
     .default_toml = "72",
     .help = "the ADS1115's I²C address (0x48 to 0x4B)"},
    {.key = "pot_calibration",
     .type = KeyType::NumberList,
     .items = {4, 4},
     .help = "an ADC sensor, required: `[counts_a, deg_a, counts_b, deg_b]` read at two angles"},
    {.key = "open_below_counts",
     .type = KeyType::Integer,
     .range = closed(0.0, 32768.0),
     .default_note = "none",
     .help = "a broken-wire guard: a reading below this is a fault (within the ADC's range)"},
    {.key = "open_above_counts",
     .type = KeyType::Integer,
     .range = closed(0.0, 32768.0),
     .default_note = "none",
     .help = "a broken-wire guard: a reading above this is a fault (within the ADC's range)"},
    {.key = "average_samples",
     .type = KeyType::Integer,
     .range = closed(1.0, 64.0),
     .default_toml = "4",
     .help = "readings averaged"},
    {.key = "brake",
     .type = KeyType::GpioLine,
     .default_note = "none: no brake",
     .help = "the brake's release line (active = solenoid energised, brake off); the motor "
             "is driven only once it has been on for brake_release_s"},
    {.key = "brake_active_low",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the brake's relay is energised by a low level"},
    relay_number("brake_release_s", "s", above_up_to(0.0, 10.0), "1.0",
                 "from the brake line on to the brake off (a T-2X: 0.5 to 1 s)"),
    relay_number("brake_engage_s", "s", closed(0.0, 10.0), "0.5",
                 "from the brake line off to the brake holding: no new move until then"),
    relay_number("brake_idle_s", "s", closed(0.0, 600.0), "2.0",
                 "the motor has been still this long before the brake is applied (a stop or "
                 "fault applies it at once)"),
    {.key = "motor_adc_device",
     .type = KeyType::Text,
     .default_note = "adc_device when sensor = \"mcp3008\"",
     .help = "the MCP3008 (`/dev/spidevB.C`) of current_adc_channel and temperature_adc_channel"},
    {.key = "current_adc_channel",
     .type = KeyType::Integer,
     .range = closed(0.0, 7.0),
     .default_note = "none: current not watched",
     .help = "the MCP3008 input wired to the IBT-2's IS pins (R_IS and L_IS joined, through a "
             "resistor to ground)"},
    relay_number("amps_per_volt", "A/V", above_up_to(0.0, 1000.0), "8.5",
                 "motor current per volt at IS: k_ILIS / R_IS (8500 / 1 kΩ typical; measure it)"),
    relay_number("current_offset_v", "V", closed(0.0, 5.0), "0.0",
                 "the IS voltage with the motor at rest"),
    {.key = "current_limit_a",
     .type = KeyType::Number,
     .unit = "A",
     .range = above_up_to(0.0, 200.0),
     .default_note = "none: required with current_adc_channel",
     .help = "the axis trips above this current held current_trip_s"},
    relay_number("current_trip_s", "s", above_up_to(0.0, 60.0), "0.5",
                 "longer than the motor's start surge, shorter than a stall may last"),
    {.key = "temperature_adc_channel",
     .type = KeyType::Integer,
     .range = closed(0.0, 7.0),
     .default_note = "none: temperature not watched",
     .help = "the MCP3008 input of a temperature sensor on the motor (an LM35)"},
    relay_number("temperature_c_per_v", "°C/V", above_up_to(0.0, 1000.0), "100.0",
                 "the sensor's scale: 100 for an LM35 or TMP36 (10 mV/°C)"),
    relay_number("temperature_offset_c", "°C", closed(-100.0, 100.0), "0.0",
                 "the temperature at 0 V: 0 for an LM35, −50 for a TMP36"),
    {.key = "temperature_limit_c",
     .type = KeyType::Number,
     .unit = "°C",
     .range = closed(0.0, 200.0),
     .default_note = "none: required with temperature_adc_channel",
     .help = "the axis trips above this motor temperature"},
    relay_number("temperature_hysteresis_c", "°C", closed(0.0, 50.0), "5.0",
                 "a temperature trip may be reset only below the limit less this"),
    {.key = "driver_fault",
     .type = KeyType::GpioLine,
     .default_note = "none",
     .help = "an input the motor driver asserts on a fault (a stepper driver's ALM): the axis "
             "trips"},
    {.key = "driver_fault_active_low",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the driver's fault line is asserted low"},
}};

static_assert(control::MovingAverage::kCapacity == 64, "[hardware.*] average_samples' range");

/// The pol axis's sensor names: the ADCs only (the EncoderHub's frames carry two angles).
constexpr std::array<std::string_view, 2> kPolSensorNames{"mcp3008", "ads1115"};

/// [hardware.pol]: [hardware.az]'s keys, with a sensor that must be given and is never the hub.
constexpr std::array<KeySpec, kHardwareAxis.size()> pol_axis_keys() {
  std::array<KeySpec, kHardwareAxis.size()> keys = kHardwareAxis;
  for (KeySpec& k : keys) {
    if (k.key != "sensor") continue;
    k.choices = kPolSensorNames;
    k.default_toml = "";
    k.default_note = "none: required";
    k.help =
        "a pot read by an ADC: `mcp3008` (spidev, 10 bits of 3.3 V) or `ads1115` (i2c-dev, "
        "±4.096 V, 15 bits), with the `adc_*` keys and `pot_calibration`; the EncoderHub "
        "reads azimuth and elevation only";
  }
  return keys;
}
constexpr std::array<KeySpec, kHardwareAxis.size()> kHardwarePolAxis = pol_axis_keys();

constexpr std::array<SectionSpec, 9> kSections{{
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
    {.name = "hardware", .chapter = Chapter::Antenna, .title = "Per-axis hardware"},
    {.name = "hardware.power",
     .chapter = Chapter::Antenna,
     .keys = kMotorPower,
     .title = "The motors' power relay",
     .help = "Switched off while the satellite schedule has nothing to do for a long while "
             "([satellites.md](satellites.md) \"The schedule\"), on again before the next "
             "pre-position; motion is held while it is off. Any backend."},
    {.name = "hardware.az",
     .chapter = Chapter::Antenna,
     .keys = kHardwareAxis,
     .title = "The azimuth axis's drive and sensor",
     .help = "For `[antenna] backend = \"hardware\"`; wiring in [hardware.md](hardware.md)."},
    {.name = "hardware.el",
     .chapter = Chapter::Antenna,
     .keys = kHardwareAxis,
     .title = "The elevation axis's drive and sensor",
     .help = "As `[hardware.az]`, for the elevation axis."},
    {.name = "hardware.pol",
     .chapter = Chapter::Antenna,
     .keys = kHardwarePolAxis,
     .title = "The polarisation axis's drive and sensor",
     .help = "As `[hardware.az]`, for the axis of `[mount.pol]` (needed with `backend = "
             "\"hardware\"` and `[mount.pol]`; [eme.md](eme.md) \"Polarisation axis\"): the "
             "sensor is a pot on an ADC, and `drive = \"pwm\"` is the `[pwm]` pol_* channels."},
}};

}  // namespace

std::span<const SectionSpec> antenna_sections() { return kSections; }

}  // namespace azt::app
