#include "config/pulse_sensor_config.hpp"

#include <array>
#include <string_view>

#include "config/actuator_config.hpp"
#include "config/config_file.hpp"

namespace azt::app {
namespace {

/// The pulse keys that say what is wired (they have no default): refused on any other sensor, so
/// a home switch written under a pot axis is an error rather than wiring that does nothing. The
/// homing's tuning keys have defaults and, as every key with one, load alone (ignored).
/// (The actuator's triangle is refused by read_hardware_axis unless a sensor measures length.)
constexpr std::array<std::string_view, 7> kPulseWiringKeys{
    "pulse_line",     "pulse_a",       "pulse_b", "home_switch",
    "counts_per_deg", "counts_per_mm", "home_mm"};

void refuse_pulse_keys(const ConfigSection& s) {
  for (std::string_view key : kPulseWiringKeys) {
    if (s.has(key)) s.fail(key, "is for sensor = \"pulses\"");
  }
}

/// One line (a reed or Hall sensor: pulse_line) or two (quadrature: pulse_a and pulse_b).
void read_lines(const ConfigSection& s, HardwareAxisConfig& a, const std::string& chip) {
  const bool low = s.boolean("pulse_active_low").value_or(false);
  const auto single = read_gpio_line(s, "pulse_line", chip, low);
  const auto qa = read_gpio_line(s, "pulse_a", chip, low);
  const auto qb = read_gpio_line(s, "pulse_b", chip, low);
  auto& counter = a.pulses->counter;
  if (single && !qa && !qb) {
    counter.kind = control::PulseInputKind::SingleChannel;
    a.pulse_lines = {*single};
  } else if (!single && qa && qb) {
    counter.kind = control::PulseInputKind::Quadrature;
    a.pulse_lines = {*qa, *qb};
  } else {
    s.fail("pulse_line",
           "sensor = \"pulses\" needs pulse_line (a reed or Hall sensor), or pulse_a and pulse_b "
           "(a quadrature pair), not both");
  }
  counter.min_spacing_s = s.number("pulse_min_spacing_s").value_or(counter.min_spacing_s);
  counter.reversed = s.boolean("pulse_reversed").value_or(false);
  if (counter.reversed && counter.kind != control::PulseInputKind::Quadrature) {
    s.fail("pulse_reversed", "is for a quadrature pair (pulse_a, pulse_b)");
  }
  if (auto ok = control::PulseCounterConfig::make(counter); !ok) {
    fail_field(s, "pulse_", ok.error().message);
  }
  a.home_switch =
      read_gpio_line(s, "home_switch", chip, s.boolean("home_active_low").value_or(false));
  if (!a.home_switch) s.fail("home_switch", "is needed by sensor = \"pulses\" (its reference)");
}

/// counts_per_deg with home_deg, or counts_per_mm with home_mm and the actuator's triangle.
void read_scale(const ConfigSection& s, control::PulseAxisConfig& p) {
  const auto per_deg = s.number("counts_per_deg");
  const auto per_mm = s.number("counts_per_mm");
  if (per_deg.has_value() == per_mm.has_value()) {
    s.fail("counts_per_deg",
           "sensor = \"pulses\" needs counts_per_deg (a rotator) or counts_per_mm (a linear "
           "actuator), one of them");
  }
  if (per_deg) {
    if (s.has("home_mm")) s.fail("home_mm", "is for counts_per_mm: give home_deg");
    p.scale = {control::PulseUnit::Degrees, *per_deg, s.number("home_deg").value_or(0.0)};
  } else {
    if (s.has("home_deg")) s.fail("home_deg", "is for counts_per_deg: give home_mm");
    const auto home_mm = s.number("home_mm");
    if (!home_mm) s.fail("home_mm", "is needed by counts_per_mm: the actuator's length at home");
    p.scale = {control::PulseUnit::Millimetres, *per_mm, *home_mm};
    p.geometry = read_actuator(s, "counts_per_mm");
  }
  std::optional<control::ActuatorGeometry> geometry;
  if (p.geometry) geometry = control::ActuatorGeometry(*p.geometry);
  if (auto ok = control::PulseScale::make(p.scale, geometry); !ok) {
    s.fail(per_deg ? "home_deg" : "home_mm", ok.error().message);
  }
}

void read_homing(const ConfigSection& s, control::PulseAxisConfig& p) {
  control::HomingConfig& h = p.homing;
  p.home_at_start = s.boolean("home_at_start").value_or(true);
  h.seek_duty = s.number("home_seek_duty").value_or(h.seek_duty);
  h.slow_duty = s.number("home_slow_duty").value_or(h.slow_duty);
  h.reapproach = s.boolean("home_reapproach").value_or(h.reapproach);
  h.stop_s = s.number("home_stop_s").value_or(h.stop_s);
  h.backoff_s = s.number("home_backoff_s").value_or(h.backoff_s);
  h.phase_timeout_s = s.number("home_phase_timeout_s").value_or(h.phase_timeout_s);
  h.max_travel_counts = s.integer("home_max_travel_counts").value_or(h.max_travel_counts);
  h.no_pulse_s = s.number("home_no_pulse_s").value_or(h.no_pulse_s);
  h.tolerance_counts = s.integer("home_tolerance_counts").value_or(h.tolerance_counts);
  if (auto ok = control::HomingConfig::make(h); !ok) fail_field(s, "home_", ok.error().message);
}

/// A setpoint box closes its loop on its own pot: it cannot be driven to a counted position.
void check_drive(const ConfigSection& s, const HardwareAxisConfig& a) {
  switch (a.drive) {
    case AxisDriveKind::Pwm:
    case AxisDriveKind::Relay:
    case AxisDriveKind::StepDir:
      return;
    case AxisDriveKind::Pot:
      s.fail("sensor",
             "is \"pulses\", but drive = \"pot\" follows the rotator box's own pot: count pulses "
             "with a pwm, relay or stepdir drive");
  }
}

}  // namespace

void read_pulse_sensor(const ConfigSection& s, HardwareAxisConfig& a, const std::string& chip) {
  switch (a.sensor) {
    case AxisSensorKind::Pulses:
      break;
    case AxisSensorKind::Hub:
    case AxisSensorKind::Mcp3008:
    case AxisSensorKind::Ads1115:
      refuse_pulse_keys(s);
      return;
  }
  check_drive(s, a);
  a.pulses.emplace();
  read_lines(s, a, chip);
  read_scale(s, *a.pulses);
  read_homing(s, *a.pulses);
}

}  // namespace azt::app
