#pragma once
// [hardware.az] / [hardware.el] / [hardware.pol]: how each axis of the `hardware` backend is
// driven and read (every drive and sensor of the seeds, chosen per axis; docs/hardware.md).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "azt/control/brake.hpp"
#include "azt/control/motor_trips.hpp"
#include "azt/control/pot_calibration.hpp"
#include "azt/control/pulse_axis.hpp"
#include "azt/control/relay_drive.hpp"
#include "azt/control/setpoint_drive.hpp"
#include "azt/control/step_dir.hpp"
#include "azt/linux/gpio.hpp"
#include "config/config_choice.hpp"

namespace azt::app {

class ConfigFile;
class ConfigSection;

/// How an axis is turned: an IBT-2 H-bridge on [pwm], relays on GPIO, an MCP41010 digital pot
/// in place of the rotator box's control pot, or a stepper's step/dir driver.
enum class AxisDriveKind { Pwm, Relay, Pot, StepDir };
/// How an axis is read: the EncoderHub on [hub], a potentiometer on an MCP3008 or ADS1115, or
/// pulses counted on GPIO lines from a home switch.
enum class AxisSensorKind { Hub, Mcp3008, Ads1115, Pulses };

/// Whether the axis is read through the EncoderHub rather than by the Pi itself. A switch, so that
/// a new kind of sensor is a compile error here rather than a pot assumed.
constexpr bool read_by_hub(AxisSensorKind sensor) {
  switch (sensor) {
    case AxisSensorKind::Hub:
      return true;
    case AxisSensorKind::Mcp3008:
    case AxisSensorKind::Ads1115:
    case AxisSensorKind::Pulses:
      return false;
  }
  return false;
}

/// Whether the axis is a potentiometer on one of the Pi's ADCs.
constexpr bool read_by_adc(AxisSensorKind sensor) {
  switch (sensor) {
    case AxisSensorKind::Mcp3008:
    case AxisSensorKind::Ads1115:
      return true;
    case AxisSensorKind::Hub:
    case AxisSensorKind::Pulses:
      return false;
  }
  return false;
}

/// The converter of an axis's motor current and temperature channels.
enum class MotorAdcKind { Mcp3008, Ads1115 };
inline constexpr ConfigChoices<MotorAdcKind, 2> kMotorAdcKinds{
    {{"mcp3008", MotorAdcKind::Mcp3008}, {"ads1115", MotorAdcKind::Ads1115}}};

inline constexpr ConfigChoices<AxisDriveKind, 4> kAxisDriveKinds{
    {{"pwm", AxisDriveKind::Pwm},
     {"relay", AxisDriveKind::Relay},
     {"pot", AxisDriveKind::Pot},
     {"stepdir", AxisDriveKind::StepDir}}};
inline constexpr ConfigChoices<AxisSensorKind, 4> kAxisSensorKinds{
    {{"hub", AxisSensorKind::Hub},
     {"mcp3008", AxisSensorKind::Mcp3008},
     {"ads1115", AxisSensorKind::Ads1115},
     {"pulses", AxisSensorKind::Pulses}}};
/// actuator_extend: which way the axis turns as the actuator extends.
inline constexpr ConfigChoices<control::ActuatorSense, 2> kActuatorSenses{
    {{"raises", control::ActuatorSense::ExtendRaises},
     {"lowers", control::ActuatorSense::ExtendLowers}}};

struct HardwareAxisConfig {
  std::string name;  ///< "az", "el" or "pol"
  AxisDriveKind drive = AxisDriveKind::Pwm;
  AxisSensorKind sensor = AxisSensorKind::Hub;

  // drive = "pwm": the IBT-2's R_EN + L_EN on a GPIO line (absent: tied to 3.3 V); drive =
  // "stepdir": the driver's ENABLE.
  std::optional<linux_os::GpioLineSpec> enable;

  // drive = "relay": forward/reverse lines (CW/CCW, UP/DOWN), or power + polarity (seed 002).
  std::optional<linux_os::GpioLineSpec> relay_forward;
  std::optional<linux_os::GpioLineSpec> relay_reverse;
  std::optional<linux_os::GpioLineSpec> relay_power;
  std::optional<linux_os::GpioLineSpec> relay_polarity;
  control::RelayDriveConfig relay;
  double polarity_settle_s = 0.05;

  // drive = "pot": an MCP41010 in place of the rotator box's control pot (seed 001).
  std::string spi_device;
  std::uint32_t spi_hz = 1'000'000;
  control::SetpointCalibration wiper;
  double setpoint_band_deg = 2.0;

  // drive = "stepdir": STEP on a sysfs PWM channel, DIR on a GPIO line (docs/hardware.md).
  std::string step_chip = "/sys/class/pwm/pwmchip0";
  unsigned step_channel = 0;
  std::optional<linux_os::GpioLineSpec> step_dir;
  control::StepDirConfig steps;

  // sensor = "mcp3008" (spidev) or "ads1115" (i2c-dev): a potentiometer on the axis.
  std::string adc_device;
  unsigned adc_channel = 0;
  std::uint8_t adc_address = 0x48;  ///< ads1115
  control::PotInputConfig pot;

  // sensor = "pulses": a reed or Hall sensor's line, or a quadrature pair (A, then B), and the
  // home switch; what the core's PulseAxis counts and homes (pulse_sensor_config.hpp).
  std::vector<linux_os::GpioLineSpec> pulse_lines;
  std::optional<linux_os::GpioLineSpec> home_switch;
  std::optional<control::PulseAxisConfig> pulses;

  // The motor's brake and protection, any drive (docs/hardware.md "Brake, current and
  // temperature"): the brake's release line and timing; the current (an IBT-2's IS pin) and
  // the temperature (an LM35) on an MCP3008's or an ADS1115's channels; the driver's fault line.
  std::optional<linux_os::GpioLineSpec> brake;
  control::BrakeConfig brake_timing;
  MotorAdcKind motor_adc = MotorAdcKind::Mcp3008;
  std::string motor_adc_device;           ///< the ADC of the current and temperature channels
  std::uint8_t motor_adc_address = 0x48;  ///< motor_adc = "ads1115"
  std::optional<unsigned> current_adc_channel;
  control::CurrentSense current;
  std::optional<unsigned> temperature_adc_channel;
  double temperature_c_per_v = 100.0;  ///< an LM35: 10 mV/°C
  double temperature_offset_c = 0.0;   ///< the temperature at 0 V (a TMP36: −50 °C)
  std::optional<linux_os::GpioLineSpec> driver_fault;
  /// The trips' limits (axis = name); used when the axis has a motor input.
  control::MotorTripsConfig trips;

  [[nodiscard]] bool has_motor_inputs() const {
    return current_adc_channel || temperature_adc_channel || driver_fault;
  }

  /// The GPIO lines this axis uses (relays, bridge enables, the brake, the driver's fault, a
  /// pulse sensor's lines and its home switch).
  [[nodiscard]] std::vector<const linux_os::GpioLineSpec*> gpio_lines() const {
    std::vector<const linux_os::GpioLineSpec*> out;
    for (const auto* l : {&relay_forward, &relay_reverse, &relay_power, &relay_polarity, &enable,
                          &step_dir, &brake, &driver_fault, &home_switch}) {
      if (*l) out.push_back(&**l);
    }
    for (const auto& l : pulse_lines) out.push_back(&l);
    return out;
  }

  [[nodiscard]] std::string key(const std::string& field) const {
    return "[hardware." + name + "] " + field;
  }
};

/// One axis with the defaults (IBT-2 on [pwm], EncoderHub).
HardwareAxisConfig default_axis(const std::string& name);

/// [hardware.power]: the motors' supply on a relay (docs/satellites.md "The schedule").
struct MotorPowerConfig {
  linux_os::GpioLineSpec relay;  ///< chip "sim": the sim backend's simulated line
  double on_lead_s = 5.0;
  [[nodiscard]] bool simulated() const { return relay.chip == "sim"; }
};

struct HardwareConfig {
  HardwareAxisConfig az = default_axis("az");
  HardwareAxisConfig el = default_axis("el");
  /// [hardware.pol]: the polarisation axis of [mount.pol], if the file has the table. Never read
  /// by the hub (the EncoderHub reads azimuth and elevation only: refused when read).
  std::optional<HardwareAxisConfig> pol;
  /// False when [mount.el] fixed_deg says the elevation does not move: `el` is then not used.
  bool el_axis = true;
  [[nodiscard]] bool uses_hub() const {
    return read_by_hub(az.sensor) || (el_axis && read_by_hub(el.sensor));
  }
  std::optional<MotorPowerConfig> power;
  /// az, el (unless fixed), and pol when there is one.
  [[nodiscard]] std::vector<const HardwareAxisConfig*> axes() const {
    std::vector<const HardwareAxisConfig*> out{&az};
    if (el_axis) out.push_back(&el);
    if (pol) out.push_back(&*pol);
    return out;
  }
  [[nodiscard]] bool uses_gpio() const {
    for (const auto* a : axes()) {
      if (!a->gpio_lines().empty()) return true;
    }
    return power && !power->simulated();
  }
};

/// A core settings check's words ("release_s must be …") on the key they name: `prefix` + their
/// first word. Throws UsageError.
[[noreturn]] void fail_field(const ConfigSection& s, const std::string& prefix,
                             const std::string& message);

/// A GPIO line key of `s`: a number on `chip`, or "CHIP:N"; nullopt when absent. Errors name it.
std::optional<linux_os::GpioLineSpec> read_gpio_line(const ConfigSection& s, const std::string& key,
                                                     const std::string& chip, bool active_low);

/// One axis's table ([hardware.az|el|pol] `s`, named `name`): its drive, its sensor, its brake and
/// motor inputs, every key checked; `chip` is [gpio] chip (lines given as bare numbers). The
/// simulation reads [hardware.el] through it too, to fly the same actuator (sim_actuator_config).
/// Throws UsageError naming the key.
HardwareAxisConfig read_hardware_axis(const ConfigSection& s, const std::string& name,
                                      const std::string& chip);

/// Reads [hardware]; `gpio_chip` is [gpio] chip (relay lines given as bare numbers); `el_axis`
/// false: [mount.el] fixed_deg, and a [hardware.el] table is refused. Throws UsageError naming
/// the key.
HardwareConfig read_hardware(const ConfigFile& file, const std::string& gpio_chip, bool el_axis);

}  // namespace azt::app
