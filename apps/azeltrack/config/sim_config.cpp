#include "config/sim_config.hpp"

#include <algorithm>
#include <cstdint>
#include <initializer_list>

#include "azt/proto/hub_frame.hpp"
#include "config/config_file.hpp"
#include "config/hardware_config.hpp"
#include "config/motor_keys.hpp"
#include "config/pointing_config.hpp"
#include "config/pol_config.hpp"
#include "config/sim_actuator_config.hpp"
#include "config/station_setup_config.hpp"

namespace azt::app {
namespace {

/// The simulated plant of one axis: the mount's rate and encoders ([mount.az]), with its own
/// imperfections (by default the ones the controller is told of) and start angle and stops.
sim::AxisParams read_plant(const ConfigSection& s, const AxisMount& mount,
                           const sim::AxisParams& defaults) {
  sim::AxisParams p = defaults;
  p.max_rate_deg_s = mount.max_rate_deg_s;
  p.encoder_bits = mount.encoder_bits;
  p.time_constant_s = s.number("time_constant_s").value_or(mount.time_constant_s);
  p.backlash_deg = s.number("backlash_deg").value_or(mount.backlash_deg);
  p.stiction_duty = s.number("stiction_duty").value_or(mount.min_duty);
  p.min_deg = s.number("min_deg").value_or(p.min_deg);
  p.max_deg = s.number("max_deg").value_or(p.max_deg);
  // Unless given, the antenna starts where the travel allows (an elevation limit above 0°).
  const bool travel = p.min_deg < p.max_deg;  // else validate() says so
  p.start_deg = s.number("start_deg")
                    .value_or(travel ? std::clamp(p.start_deg, p.min_deg, p.max_deg) : p.start_deg);
  if (auto ok = p.validate(); !ok) {
    // "start_deg must be within …": the key the message begins with is the one at fault.
    const std::string& message = ok.error().message;
    const auto space = message.find(' ');
    s.fail(message.substr(0, space), message.substr(space + 1));
  }
  return p;
}

/// `fault = "frozen_shaft" | "reversed_motor" | "encoder_offset"` starting `fault_at_s` seconds
/// after the start (`fault_counts` for the offset): a plant fault to rehearse, or to test the
/// station's refusals against.
void read_plant_fault(const ConfigSection& s, bool azimuth, sim::PlantSetup& plant) {
  const auto kind = s.text("fault");
  if (!kind) return;
  sim::AxisFault fault;
  // One of the schema's choices; "frozen_shaft" is the fault's default kind.
  if (*kind == "reversed_motor") fault.kind = sim::AxisFaultKind::ReversedMotor;
  if (*kind == "encoder_offset") {
    fault.kind = sim::AxisFaultKind::EncoderOffset;
    fault.counts = static_cast<std::int32_t>(s.integer("fault_counts").value_or(100));
  }
  const double at_s = s.number("fault_at_s").value_or(0.0);
  plant.faults.push_back(sim::ScheduledFault{at_s, azimuth, fault});
}

void read_link(const ConfigSection& s, sim::PlantSetup& plant) {
  if (s.text("frame_version").value_or("crc8") == "seed") {
    plant.frame_version = proto::HubFrameVersion::Seed;
  }
  plant.link.frame_loss = s.number("frame_loss").value_or(0.0);
  plant.link.byte_corruption = s.number("byte_corruption").value_or(0.0);
  if (auto seed = s.integer("seed")) plant.seed = static_cast<std::uint64_t>(*seed);
}

/// Keys that mean something only with `needed` (`needed_words`: the key that gives it) are
/// refused without it, rather than left to do nothing.
void refuse_without(const ConfigSection& s, bool needed, const std::string& needed_words,
                    std::initializer_list<const char*> keys) {
  if (needed) return;
  for (const char* key : keys) {
    if (s.has(key)) s.fail(key, "needs " + needed_words);
  }
}

/// `brake = true`: the plant's brake (its own lift and hold times) and the controller's timing
/// for it, read as a real axis's ([hardware.az] brake_release_s …).
void read_plant_brake(const ConfigSection& s, std::size_t axis, sim::PlantSetup& plant,
                      sim::AxisMotorControl& motor) {
  sim::BrakePlantParams b;
  b.release_s = s.number("brake_lift_s").value_or(b.release_s);
  b.engage_s = s.number("brake_hold_s").value_or(b.engage_s);
  if (auto ok = b.validate(); !ok) s.fail("brake_lift_s", ok.error().message);  // the schema's
  plant.brakes.at(axis) = b;
  motor.brake = read_brake_timing(s);
}

/// `motor_heating = true`: the plant's winding and the controller's temperature trip on it (the
/// simulated station reads the winding as a temperature sensor on the motor).
void read_plant_heating(const ConfigSection& s, std::size_t axis, sim::PlantSetup& plant,
                        sim::AxisMotorControl& motor) {
  sim::MotorThermalParams t;
  t.ambient_c = s.number("ambient_c").value_or(t.ambient_c);
  t.rise_at_full_duty_c = s.number("motor_rise_c").value_or(t.rise_at_full_duty_c);
  t.time_constant_s = s.number("motor_time_constant_s").value_or(t.time_constant_s);
  t.start_c = s.number("motor_start_c").value_or(t.ambient_c);
  if (auto ok = t.validate(); !ok) s.fail("motor_rise_c", ok.error().message);  // the schema's
  plant.thermal.at(axis) = t;
  control::MotorTripsConfig trips;
  trips.axis = axis == 0 ? "az" : "el";
  trips.temperature_limit_c = s.number("temperature_limit_c");
  read_temperature_hysteresis(s, trips);
  if (auto ok = control::MotorTripsConfig::make(trips); !ok) fail_field(s, "", ok.error().message);
  motor.trips = trips;
}

/// [sim.az|el] brake and motor_heating for axis 0 or 1 (`driven`: false for a fixed elevation).
sim::AxisMotorControl read_plant_motor(const ConfigSection& s, std::size_t axis, bool driven,
                                       sim::PlantSetup& plant) {
  sim::AxisMotorControl motor;
  const bool brake = s.boolean("brake").value_or(false);
  const bool heating = s.boolean("motor_heating").value_or(false);
  if (!driven && (brake || heating)) {
    s.fail(brake ? "brake" : "motor_heating",
           "is for an axis that moves, and [mount.el] fixed_deg says this one does not");
  }
  refuse_without(
      s, brake, "brake = true",
      {"brake_lift_s", "brake_hold_s", "brake_release_s", "brake_engage_s", "brake_idle_s"});
  refuse_without(s, heating, "motor_heating = true",
                 {"ambient_c", "motor_rise_c", "motor_time_constant_s", "motor_start_c",
                  "temperature_hysteresis_c"});
  // Required with the winding, refused without it: as a temperature input on real hardware.
  (void)read_trip_limit(s, "temperature_limit_c", heating, "motor_heating = true",
                        "the simulated winding's temperature");
  if (brake) read_plant_brake(s, axis, plant, motor);
  if (heating) read_plant_heating(s, axis, plant, motor);
  return motor;
}

}  // namespace

std::array<sim::AxisMotorControl, 2> sim_motors_from(const ConfigFile& file,
                                                     sim::PlantSetup& plant) {
  const ConfigSection s = file.section("sim");
  return {read_plant_motor(s.child("az"), 0, true, plant),
          read_plant_motor(s.child("el"), 1, plant.el_axis, plant)};
}

sim::PlantSetup plant_setup_from(const ConfigFile& file, const MountConfig& mount,
                                 const control::StationSetup& station) {
  sim::PlantSetup plant;
  const ConfigSection sim_section = file.section("sim");
  // The plants' end stops are the travel's unless given.
  sim::AxisParams az_defaults;
  az_defaults.min_deg = station.az_range.min_deg;
  az_defaults.max_deg = station.az_range.max_deg;
  sim::AxisParams el_defaults;
  el_defaults.min_deg = station.el_range.min_deg;
  el_defaults.max_deg = station.el_range.max_deg;
  plant.az = read_plant(sim_section.child("az"), mount.az, az_defaults);
  plant.el = read_plant(sim_section.child("el"), mount.el, el_defaults);
  read_plant_fault(sim_section.child("az"), true, plant);
  read_plant_fault(sim_section.child("el"), false, plant);
  read_link(sim_section, plant);
  const ConfigSection pol = sim_section.child("pol");  // its keys are checked even unused
  if (mount.pol) {
    // The pol plant's end stops are its travel's; it has no scheduled faults of its own yet.
    sim::AxisParams pol_defaults;
    pol_defaults.min_deg = mount.pol->min_deg;
    pol_defaults.max_deg = mount.pol->max_deg;
    plant.pol = read_plant(pol, mount.pol->axis, pol_defaults);
  } else if (pol.present()) {
    file.fail("[sim.pol] models the axis of [mount.pol], which the file does not have");
  }
  plant.pointing_errors = mount_errors_from(sim_section);
  if (station.el_fixed_deg) {
    // The array stands at its fixed angle, whatever [sim.el] says: nothing would move it there.
    plant.el_axis = false;
    plant.el.start_deg = *station.el_fixed_deg;
  } else {
    plant.el_actuator = sim_actuator_from(file, plant.el);
  }
  return plant;
}

SimHubConfig sim_hub_from(const ConfigFile& file) {
  const ConfigSection s = file.section("sim");
  SimHubConfig hub;
  hub.firmware = s.text("hub").value_or("model") == "firmware";
  hub.elf = s.text("hub_firmware").value_or("");
  return hub;
}

SimReceiverConfig sim_receiver_from(const ConfigFile& file) {
  const ConfigSection s = file.section("sim").child("receiver");
  SimReceiverConfig c;
  sim::ReceiverSetup& r = c.receiver;
  // The ranges are the schema's (config/schema_sim_keys.cpp).
  r.beamwidth_deg = s.number("beamwidth_deg").value_or(r.beamwidth_deg);
  r.tsys_k = s.number("tsys_k").value_or(r.tsys_k);
  r.rate_hz = s.number("rate_hz").value_or(r.rate_hz);
  r.dish_m = s.number("dish_m").value_or(r.dish_m);
  r.efficiency = s.number("efficiency").value_or(r.efficiency);
  c.sun_k = s.number("sun_k").value_or(c.sun_k);
  c.moon_k = s.number("moon_k").value_or(c.moon_k);
  r.noise_db = s.number("noise_db").value_or(r.noise_db);
  if (auto seed = s.integer("seed")) r.seed = static_cast<std::uint64_t>(*seed);
  c.flux_mhz = s.integer("flux_mhz").value_or(c.flux_mhz);
  return c;
}

SimConfig sim_config_from(const ConfigFile& file) {
  SimConfig config;
  config.sky = sky_config_from(file);
  config.mount = mount_config_from(file);
  config.setup.station = station_setup_from(file, config.mount);
  config.setup.plant = plant_setup_from(file, config.mount, config.setup.station);
  config.setup.motors = sim_motors_from(file, config.setup.plant);
  config.hub = sim_hub_from(file);
  config.receiver = sim_receiver_from(file);
  config.pol = pol_settings_from(file);
  return config;
}

}  // namespace azt::app
