// The `hardware` backend (and `pwm`, its both-axes-on-IBT-2-and-EncoderHub form): the one station
// backend over each axis's own drive and sensor (axis_devices.hpp), and the polarisation axis's
// when [hardware.pol] gives them (a pot on an ADC or a pulse count: the EncoderHub reads az and
// el only). The mount's rates and encoder resolutions are [mount.az] / [mount.el], the travel is
// [geometry]. The EncoderHub reports its jumpers' bits in every frame: a frame whose bits are not
// the mount's is never used, and latches a fault naming both (azt/linux/hub_sensors.hpp).
#include "antenna/antenna_backend.hpp"
#include "antenna/axis_devices.hpp"
#include "antenna/station_backend.hpp"
#include "azt/control/station_setup.hpp"
#include "azt/linux/hub_sensors.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

control::AxisDriveConfig drive_config(const HardwareAxisConfig& a) {
  control::AxisDriveConfig d;
  switch (a.drive) {
    case AxisDriveKind::Pwm:
      d.kind = control::DriveKind::Pwm;
      break;
    case AxisDriveKind::Relay:
      d.kind = control::DriveKind::Relay;
      d.relay = a.relay;
      break;
    case AxisDriveKind::Pot:
      d.kind = control::DriveKind::Setpoint;
      d.setpoint_band_deg = a.setpoint_band_deg;
      break;
    case AxisDriveKind::StepDir:
      // A step rate in proportion to the duty: to the controller, a PWM bridge without load.
      d.kind = control::DriveKind::Pwm;
      break;
  }
  if (a.brake) d.brake = a.brake_timing;
  if (a.has_motor_inputs()) d.trips = a.trips;
  if (a.pulses) d.pulses = *a.pulses;
  if (a.pot.actuator) d.sensor_step_deg = a.pot.max_deg_per_count();  // read_adc sets it
  return d;
}

control::StationControlConfig control_config(const DaemonConfig& config) {
  control::StationControlConfig c = config.station.control_config();
  c.az_drive = drive_config(config.hardware.az);
  c.el_drive = drive_config(config.hardware.el);
  c.az_absolute = !read_by_hub(config.hardware.az.sensor);
  if (c.pol && config.hardware.pol) c.pol->drive = drive_config(*config.hardware.pol);
  return c;
}

/// An axis's own sensor into `sensor`: a pot on an ADC; or its pulse count into `pulses` (the
/// hub's are opened together).
void open_sensor(const HardwareAxisConfig& a, HardwarePorts& devices,
                 std::unique_ptr<ports::AxisSensor>& sensor,
                 std::unique_ptr<ports::PulseInput>& pulses) {
  switch (a.sensor) {
    case AxisSensorKind::Hub:
      return;
    case AxisSensorKind::Mcp3008:
    case AxisSensorKind::Ads1115:
      sensor = open_adc_sensor(a, devices);
      return;
    case AxisSensorKind::Pulses:
      pulses = open_pulse_input(a, devices);
      return;
  }
}

/// Sensors first, then drives: a drive is only ever opened once everything it needs exists
/// (an open drive is off again when destroyed, if a later one cannot be had).
ports::StationPorts open_ports(boost::asio::io_context& io, const DaemonConfig& config,
                               HardwarePorts& devices) {
  const std::array<const HardwareAxisConfig*, 2> axes{&config.hardware.az, &config.hardware.el};
  // A fixed elevation has no drive or sensor: the station is azimuth's alone.
  const std::size_t driven = config.hardware.el_axis ? 2 : 1;
  ports::StationPorts p;
  if (config.hardware.uses_hub()) {
    linux_os::HubSensorsConfig hub{
        config.hub,
        {config.mount.az.encoder_bits, config.mount.el.encoder_bits},
        {read_by_hub(axes[0]->sensor), driven == 2 && read_by_hub(axes[1]->sensor)}};
    auto sensors = linux_os::open_hub_sensors(io, hub);
    if (!sensors) throw UsageError("[hub] device: " + sensors.error().message);
    p.sensors = std::move(sensors).value();
  }
  for (std::size_t i = 0; i < driven; ++i)
    open_sensor(*axes.at(i), devices, p.sensors.at(i), p.pulse_inputs.at(i));
  // The pol axis only with both its settings and its devices (the configuration refuses one
  // without the other: config/pol_config.hpp).
  const HardwareAxisConfig* pol = nullptr;
  if (config.station.pol && config.hardware.pol) pol = &*config.hardware.pol;
  if (pol != nullptr) open_sensor(*pol, devices, p.pol_sensor, p.pol_pulse_input);
  for (std::size_t i = 0; i < driven; ++i)
    p.motor_sensors.at(i) = open_motor_sensor(*axes.at(i), devices);
  if (pol != nullptr) p.pol_motor_sensor = open_motor_sensor(*pol, devices);
  // The brakes before the drives, opened applied: a drive is never live beside a brake line
  // that cannot be had.
  for (std::size_t i = 0; i < driven; ++i) p.brakes.at(i) = open_brake_line(*axes.at(i), devices);
  if (pol != nullptr) p.pol_brake = open_brake_line(*pol, devices);
  for (std::size_t i = 0; i < driven; ++i)
    p.drives.at(i) = open_axis_drive(*axes.at(i), config.pwm, devices);
  if (pol != nullptr) p.pol_drive = open_axis_drive(*pol, config.pwm, devices);
  return p;
}

/// An axis's drive and what reads it (a sensor, or a pulse count); "fixed" without a drive.
std::string describe_axis(const ports::AxisDrive* drive, const ports::AxisSensor* sensor,
                          const ports::PulseInput* pulses) {
  if (drive == nullptr) return "fixed";
  return drive->describe() + ", " + (sensor != nullptr ? sensor->describe() : pulses->describe());
}

std::string describe_ports(const ports::StationPorts& p) {
  std::string out =
      "az: " + describe_axis(p.drives[0].get(), p.sensors[0].get(), p.pulse_inputs[0].get()) +
      "; el: " + describe_axis(p.drives[1].get(), p.sensors[1].get(), p.pulse_inputs[1].get());
  if (p.pol_drive) {
    out +=
        "; pol: " + describe_axis(p.pol_drive.get(), p.pol_sensor.get(), p.pol_pulse_input.get());
  }
  for (const auto* brake : {p.brakes[0].get(), p.brakes[1].get(), p.pol_brake.get()}) {
    if (brake != nullptr) out += "; " + brake->describe();
  }
  for (const auto* motor :
       {p.motor_sensors[0].get(), p.motor_sensors[1].get(), p.pol_motor_sensor.get()}) {
    if (motor != nullptr) out += "; " + motor->describe();
  }
  return out;
}

}  // namespace

std::unique_ptr<AntennaBackend> make_hardware_backend(boost::asio::io_context& io,
                                                      const DaemonConfig& config,
                                                      HardwarePorts devices) {
  ports::StationPorts p = open_ports(io, config, devices);
  const std::string describe = describe_ports(p);
  return make_station_backend(control_config(config), config.station.believed_start(),
                              config.station.corrections, std::move(p), describe);
}

std::unique_ptr<AntennaBackend> make_pwm_backend(boost::asio::io_context& io,
                                                 const DaemonConfig& config) {
  DaemonConfig both_pwm = config;
  both_pwm.hardware = HardwareConfig{};  // IBT-2 bridges and the EncoderHub on both axes
  both_pwm.hardware.el_axis = config.hardware.el_axis;
  return make_hardware_backend(io, both_pwm, HardwarePorts{});
}

}  // namespace azt::app
