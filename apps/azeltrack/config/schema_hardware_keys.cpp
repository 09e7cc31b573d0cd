// The schema's per-axis hardware keys: [hardware.power], and each axis's drive, sensor, brake,
// motor protection and pulse count in [hardware.az|el|pol] (hardware_config.cpp and
// pulse_sensor_config.cpp read them; wiring in docs/hardware.md).
#include <array>

#include "config/hardware_config.hpp"
#include "config/schema_keys.hpp"
#include "config/schema_motor_keys.hpp"

namespace azt::app {
namespace {

constexpr auto kDriveNames = choice_names(kAxisDriveKinds);
constexpr auto kSensorNames = choice_names(kAxisSensorKinds);
constexpr auto kMotorAdcNames = choice_names(kMotorAdcKinds);

/// A relay-drive line: a GPIO line on [gpio] chip, or "CHIP:N".
constexpr KeySpec relay_line(std::string_view key, std::string_view help) {
  return {.key = key, .type = KeyType::GpioLine, .default_note = "none", .help = help};
}

constexpr auto kActuatorSenseNames = choice_names(kActuatorSenses);

constexpr KeySpec flag(std::string_view key, std::string_view default_toml, std::string_view help) {
  return {.key = key, .type = KeyType::Boolean, .default_toml = default_toml, .help = help};
}

/// One length of an actuator's triangle (docs/hardware.md "Linear actuators").
constexpr KeySpec actuator_mm(std::string_view key, std::string_view help) {
  return {.key = key,
          .type = KeyType::Number,
          .unit = "mm",
          .range = above_up_to(0.0, 10000.0),
          .default_note = "none: required with counts_per_mm or pot_calibration_mm",
          .help = help};
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

constexpr std::array<KeySpec, 80> kHardwareAxis{{
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
             "and `pot_calibration`); `pulses`: a reed, Hall or quadrature sensor counted on GPIO "
             "from a home switch (the `pulse_*`, `home_*` and `counts_per_*` keys)"},
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
    number_key("max_step_hz", "Hz", closed(1.0, 100000.0), "2000.0",
               "`drive = \"stepdir\"`: the step rate at full speed, `[mount.*]` rate × steps "
               "per degree"),
    number_key("start_step_hz", "Hz", closed(0.0, 100000.0), "200.0",
               "the stepper's pull-in rate: started and stopped at without a ramp"),
    number_key("step_accel_hz_s", "Hz/s", closed(1.0, 1000000.0), "4000.0",
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
    number_key("window_deg", "°", closed(0.0, 10.0), "1.0", "the relay drive's movement window"),
    number_key("lsb_deg", "°", above_up_to(0.0, 1.0), "0.3515625",
               "one step of the position reading (360/1024)"),
    number_key("coast_deg", "°", closed(0.0, 10.0), "0.0",
               "how far the axis runs on after its relay opens at full speed"),
    number_key("min_on_s", "s", closed(0.0, 10.0), "0.1",
               "an energised relay stays on at least this long"),
    number_key("reversal_dead_s", "s", above_up_to(0.0, 60.0), "0.5",
               "after a release, both directions stay off this long before a reversal"),
    number_key("polarity_settle_s", "s", closed(0.0, 1.0), "0.05",
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
    number_key("setpoint_band_deg", "°", above_up_to(0.0, 20.0), "2.0",
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
     .help = "an ADC sensor, required (or `pot_calibration_mm`): `[counts_a, deg_a, counts_b, "
             "deg_b]` read at two angles"},
    {.key = "pot_calibration_mm",
     .type = KeyType::NumberList,
     .items = {4, 4},
     .help = "or, a pot on a linear actuator: `[counts_a, mm_a, counts_b, mm_b]` read at two "
             "lengths (pin to pin), with the `actuator_*` triangle that turns length into angle"},
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
    kBrakeReleaseKey,
    kBrakeEngageKey,
    kBrakeIdleKey,
    {.key = "motor_adc",
     .type = KeyType::Choice,
     .choices = kMotorAdcNames,
     .default_toml = "\"mcp3008\"",
     .help = "the ADC of current_adc_channel and temperature_adc_channel: `mcp3008` (spidev, one "
             "transfer a tick each) or `ads1115` (i2c-dev; its conversions take turns with a pot "
             "on the same chip, which keeps every other one)"},
    {.key = "motor_adc_device",
     .type = KeyType::Text,
     .default_note = "adc_device when the pot is on an ADC of motor_adc's kind",
     .help = "the ADC of current_adc_channel and temperature_adc_channel: an MCP3008's "
             "`/dev/spidevB.C` or an ADS1115's `/dev/i2c-N`"},
    {.key = "motor_adc_address",
     .type = KeyType::Integer,
     .range = closed(72.0, 75.0),
     .default_note = "adc_address",
     .help = "`motor_adc = \"ads1115\"`: the ADS1115's I²C address (0x48 to 0x4B)"},
    {.key = "current_adc_channel",
     .type = KeyType::Integer,
     .range = closed(0.0, 7.0),
     .default_note = "none: current not watched",
     .help = "the motor ADC's input (0 to 7 on an MCP3008, 0 to 3 on an ADS1115) wired to the "
             "IBT-2's IS pins (R_IS and L_IS joined, through a resistor to ground)"},
    number_key("amps_per_volt", "A/V", above_up_to(0.0, 1000.0), "8.5",
               "motor current per volt at IS: k_ILIS / R_IS (8500 / 1 kΩ typical; measure it)"),
    number_key("current_offset_v", "V", closed(0.0, 5.0), "0.0",
               "the IS voltage with the motor at rest"),
    {.key = "current_limit_a",
     .type = KeyType::Number,
     .unit = "A",
     .range = above_up_to(0.0, 200.0),
     .default_note = "none: required with current_adc_channel",
     .help = "the axis trips above this current held current_trip_s"},
    number_key("current_trip_s", "s", above_up_to(0.0, 60.0), "0.5",
               "longer than the motor's start surge, shorter than a stall may last"),
    {.key = "temperature_adc_channel",
     .type = KeyType::Integer,
     .range = closed(0.0, 7.0),
     .default_note = "none: temperature not watched",
     .help = "the motor ADC's input (as current_adc_channel) of a temperature sensor on the motor "
             "(an LM35)"},
    number_key("temperature_c_per_v", "°C/V", above_up_to(0.0, 1000.0), "100.0",
               "the sensor's scale: 100 for an LM35 or TMP36 (10 mV/°C)"),
    number_key("temperature_offset_c", "°C", closed(-100.0, 100.0), "0.0",
               "the temperature at 0 V: 0 for an LM35, −50 for a TMP36"),
    {.key = "temperature_limit_c",
     .type = KeyType::Number,
     .unit = "°C",
     .range = closed(0.0, 200.0),
     .default_note = "none: required with temperature_adc_channel",
     .help = "the axis trips above this motor temperature"},
    kTemperatureHysteresisKey,
    {.key = "driver_fault",
     .type = KeyType::GpioLine,
     .default_note = "none",
     .help = "an input the motor driver asserts on a fault (a stepper driver's ALM): the axis "
             "trips"},
    {.key = "driver_fault_active_low",
     .type = KeyType::Boolean,
     .default_toml = "false",
     .help = "the driver's fault line is asserted low"},
    relay_line("pulse_line",
               "`sensor = \"pulses\"`: a reed or Hall sensor's line, one count per pulse (the "
               "direction is the drive's)"),
    relay_line("pulse_a", "or: a quadrature sensor's channel A, with pulse_b (×4 counting)"),
    relay_line("pulse_b", "a quadrature sensor's channel B"),
    flag("pulse_active_low", "false", "the pulse lines are active low"),
    number_key("pulse_min_spacing_s", "s", closed(0.0, 1.0), "0.01",
               "a single line's pulses closer than this are contact bounce (below the shortest "
               "pulse period at full speed)"),
    flag("pulse_reversed", "false", "a quadrature pair counts the other way (A and B swapped)"),
    relay_line("home_switch",
               "`sensor = \"pulses\"`, required: the home switch (a limit or index switch), "
               "active = closed"),
    flag("home_active_low", "false", "the home switch closes to a low level"),
    {.key = "counts_per_deg",
     .type = KeyType::Number,
     .unit = "1/°",
     .range = above_up_to(0.0, 1000000.0),
     .default_note = "none",
     .help = "`sensor = \"pulses\"` on a rotator: counts per degree of the axis (SRT: 11.7)"},
    number_key("home_deg", "°", closed(-360.0, 720.0), "0.0",
               "with counts_per_deg: the axis angle where the home switch closes"),
    {.key = "counts_per_mm",
     .type = KeyType::Number,
     .unit = "1/mm",
     .range = above_up_to(0.0, 1000000.0),
     .default_note = "none",
     .help = "or, on a linear actuator: counts per millimetre of its length, with `home_mm` and "
             "the `actuator_*` triangle"},
    {.key = "home_mm",
     .type = KeyType::Number,
     .unit = "mm",
     .range = closed(0.0, 10000.0),
     .default_note = "none",
     .help = "with counts_per_mm, required: the actuator's length (pin to pin) where the home "
             "switch closes"},
    actuator_mm("actuator_pivot_to_fixed_mm", "a: the pivot to the actuator's fixed pin"),
    actuator_mm("actuator_pivot_to_moving_mm", "b: the pivot to the actuator's moving pin"),
    {.key = "actuator_offset_deg",
     .type = KeyType::Number,
     .unit = "°",
     .range = closed(-360.0, 360.0),
     .default_note = "none",
     .help = "θ0: the angle between the two arms (a, b) where the axis reads 0°"},
    actuator_mm("actuator_retracted_mm", "the actuator's length pin to pin when retracted"),
    actuator_mm("actuator_extended_mm", "… and when extended (retracted + stroke)"),
    {.key = "actuator_extend",
     .type = KeyType::Choice,
     .choices = kActuatorSenseNames,
     .default_toml = "\"raises\"",
     .help = "extending the actuator `raises` or `lowers` the axis's angle"},
    flag("home_at_start", "true",
         "home when the daemon starts; false: the axis holds until POST /api/hardware/home"),
    number_key("home_seek_duty", "", closed(-1.0, 1.0), "-0.6",
               "the seek's duty, signed towards the switch (negative: at the low end)"),
    number_key("home_slow_duty", "", above_up_to(0.0, 1.0), "0.25",
               "the back-off's and re-approach's duty: slow, so the switch is met alike"),
    flag("home_reapproach", "true",
         "back off and come back slowly for the home count; false: the seek's edge"),
    number_key("home_stop_s", "s", closed(0.0, 60.0), "1.0",
               "at rest this long between homing's moves (the motor coasts)"),
    number_key("home_backoff_s", "s", closed(0.0, 60.0), "1.0",
               "keep backing off this long after the switch opened"),
    number_key("home_phase_timeout_s", "s", closed(1.0, 3600.0), "120.0",
               "each homing move gives up after this long"),
    {.key = "home_max_travel_counts",
     .type = KeyType::Integer,
     .range = closed(1.0, 100000000.0),
     .default_toml = "10000",
     .help = "… or after this many counts (more than the whole travel: the switch was missed)"},
    number_key("home_no_pulse_s", "s", closed(0.1, 600.0), "3.0",
               "driven this long without a pulse: homing fails (motor, sensor or wiring)"),
    {.key = "home_tolerance_counts",
     .type = KeyType::Integer,
     .range = closed(0.0, 1000.0),
     .default_toml = "1",
     .help = "a pass of the home switch may read this many counts off the home count before the "
             "position is lost (an index switch's hysteresis)"},
}};

static_assert(control::MovingAverage::kCapacity == 64, "[hardware.*] average_samples' range");

/// The pol axis's sensor names: the ADCs and a pulse count, never the hub (the EncoderHub's
/// frames carry two angles).
constexpr std::array<std::string_view, 3> kPolSensorNames{"mcp3008", "ads1115", "pulses"};

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
        "±4.096 V, 15 bits), with the `adc_*` keys and `pot_calibration`; or `pulses`: a reed, "
        "Hall or quadrature sensor counted on GPIO from a home switch (the `pulse_*`, `home_*` "
        "and `counts_per_deg` keys); the EncoderHub reads azimuth and elevation only";
  }
  return keys;
}
constexpr std::array<KeySpec, kHardwareAxis.size()> kHardwarePolAxis = pol_axis_keys();

constexpr std::array<SectionSpec, 5> kSections{{
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
             "sensor is a pot on an ADC or a pulse count, and `drive = \"pwm\"` is the `[pwm]` "
             "pol_* channels."},
}};

}  // namespace

std::span<const SectionSpec> hardware_sections() { return kSections; }

}  // namespace azt::app
