#include "config/sim_config.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "azt/control/corrections.hpp"
#include "azt/proto/hub_frame.hpp"
#include "config/config_file.hpp"

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
  p.start_deg = s.number("start_deg").value_or(p.start_deg);
  p.min_deg = s.number("min_deg").value_or(p.min_deg);
  p.max_deg = s.number("max_deg").value_or(p.max_deg);
  if (auto ok = p.validate(); !ok) s.fail("time_constant_s", ok.error().message);
  return p;
}

/// The controller's view of an axis: the [control] settings, and the mount's rate, time constant,
/// stiction, play and encoder step ([mount.az]) - never the simulated plant's.
control::AxisControlConfig control_for(const ConfigSection& c, const AxisMount& mount) {
  control::AxisControlConfig a;
  a.window_deg = c.number("window_deg").value_or(0.0);
  a.ramp_s = c.number("ramp_s").value_or(1.0);
  a.tracking_speed = c.number("tracking_speed").value_or(0.5);
  a.fast_zone_deg = c.number("fast_zone_deg").value_or(3.0);
  a.lead = c.boolean("lead").value_or(true);
  a.max_rate_deg_s = mount.max_rate_deg_s;
  a.time_constant_s = mount.time_constant_s;
  a.min_duty = mount.min_duty;
  a.backlash_deg = mount.backlash_deg;
  a.lsb_deg = proto::hub_resolution_deg(mount.encoder_bits);
  auto ok = control::AxisControlConfig::make(a);
  if (!ok) c.fail("window_deg", ok.error().message);
  return a;
}

control::SupervisorConfig supervisor_for(const AxisMount& mount) {
  control::SupervisorConfig s;
  s.max_rate_deg_s = mount.max_rate_deg_s;
  s.lsb_deg = proto::hub_resolution_deg(mount.encoder_bits);
  return s;
}

void read_geometry(const ConfigSection& g, sim::StationSimSetup& setup) {
  auto az = control::AzimuthRange::make(g.number("az_min_deg").value_or(0.0),
                                        g.number("az_max_deg").value_or(360.0));
  if (!az) g.fail("az_min_deg", az.error().message);
  auto el = control::ElevationRange::make(g.number("el_min_deg").value_or(0.0),
                                          g.number("el_max_deg").value_or(90.0));
  if (!el) g.fail("el_min_deg", el.error().message);
  setup.station.az_range = *az;
  setup.station.el_range = *el;
}

/// `[control] out_of_range = "hold" | "park"`, with the park position `park_az_deg`,
/// `park_el_deg` (default: south at the lowest elevation).
void read_out_of_range(const ConfigSection& c, sim::StationSimSetup& setup) {
  const std::string policy = c.text("out_of_range").value_or("hold");
  if (policy == "hold") return;
  if (policy != "park") c.fail("out_of_range", "must be \"hold\" or \"park\"");
  const control::AzEl park{c.number("park_az_deg").value_or(180.0),
                           c.number("park_el_deg").value_or(setup.station.el_range.min_deg)};
  if (park.az_deg < 0.0 || park.az_deg >= 360.0 ||
      !control::plan_elevation(park.el_deg, setup.station.el_range)) {
    c.fail("park_az_deg", "park position must be az 0..360 and inside the elevation range");
  }
  setup.station.park_when_out_of_range = park;
}

/// `fault = "frozen_shaft" | "reversed_motor" | "encoder_offset"` starting `fault_at_s` seconds
/// after the start (`fault_counts` for the offset): a plant fault to rehearse, or to test the
/// station's refusals against.
void read_plant_fault(const ConfigSection& s, bool azimuth, sim::StationSimSetup& setup) {
  const auto kind = s.text("fault");
  if (!kind) return;
  sim::AxisFault fault;
  if (*kind == "reversed_motor") {
    fault.kind = sim::AxisFaultKind::ReversedMotor;
  } else if (*kind == "encoder_offset") {
    fault.kind = sim::AxisFaultKind::EncoderOffset;
    const std::int64_t counts = s.integer("fault_counts").value_or(100);
    if (counts < -65535 || counts > 65535) s.fail("fault_counts", "must be -65535 to 65535");
    fault.counts = static_cast<std::int32_t>(counts);
  } else if (*kind != "frozen_shaft") {
    s.fail("fault", "must be \"frozen_shaft\", \"reversed_motor\" or \"encoder_offset\"");
  }
  const double at_s = s.number("fault_at_s").value_or(0.0);
  if (!(at_s >= 0.0)) s.fail("fault_at_s", "must be 0 or more seconds");
  setup.plant_faults.push_back(sim::ScheduledFault{at_s, azimuth, fault});
}

void read_link(const ConfigSection& s, sim::StationSimSetup& setup) {
  const std::string version = s.text("frame_version").value_or("crc8");
  if (version == "seed") {
    setup.frame_version = proto::HubFrameVersion::Seed;
  } else if (version != "crc8") {
    s.fail("frame_version", "must be \"seed\" or \"crc8\"");
  }
  setup.link.frame_loss = s.number("frame_loss").value_or(0.0);
  setup.link.byte_corruption = s.number("byte_corruption").value_or(0.0);
  for (double p : {setup.link.frame_loss, setup.link.byte_corruption}) {
    if (p < 0.0 || p > 1.0) s.fail("frame_loss", "probabilities must be 0 to 1");
  }
  if (auto seed = s.integer("seed")) setup.seed = static_cast<std::uint64_t>(*seed);
}

/// [corrections]: the seed's Offset screen, the ± / UP / DWN running totals and the tilt table.
control::PositionCorrections read_corrections(const ConfigSection& s) {
  control::PositionCorrections c;
  auto offsets = control::AxisOffsets::make(s.number("az_offset_deg").value_or(0.0),
                                            s.number("el_offset_deg").value_or(0.0));
  if (!offsets) s.fail("az_offset_deg", "/ el_offset_deg: " + offsets.error().message);
  c.offsets = *offsets;
  auto user = control::UserCorrections::from_deg(s.number("az_user_deg").value_or(0.0),
                                                 s.number("el_user_deg").value_or(0.0));
  if (!user) s.fail("az_user_deg", "/ el_user_deg: " + user.error().message);
  c.user = *user;
  if (const toml::array* tilt = s.array("tilt_el_deg")) {
    std::vector<double> entries;
    for (const auto& node : *tilt) {
      const auto v = node.value<double>();
      if (!v) s.fail("tilt_el_deg", "must hold numbers");
      entries.push_back(*v);
    }
    auto table = control::TiltTable::make(entries);
    if (!table) s.fail("tilt_el_deg", table.error().message);
    c.tilt = *table;
  }
  return c;
}

}  // namespace

SimConfig sim_config_from(const ConfigFile& file) {
  SimConfig config;
  config.station = station_config_from(file);
  sim::StationSimSetup& setup = config.setup;
  const ConfigSection sim_section =
      file.section("sim", {"az", "el", "frame_version", "frame_loss", "byte_corruption", "seed"});
  const std::initializer_list<std::string_view> plant_keys = {
      "time_constant_s", "backlash_deg", "stiction_duty", "start_deg",   "min_deg",
      "max_deg",         "fault",        "fault_at_s",    "fault_counts"};
  config.mount = mount_config_from(file);
  sim::AxisParams az_defaults;
  az_defaults.min_deg = 0.0;
  az_defaults.max_deg = 360.0;
  sim::AxisParams el_defaults;
  el_defaults.min_deg = 0.0;
  el_defaults.max_deg = 90.0;
  read_geometry(file.section("geometry", {"az_min_deg", "az_max_deg", "el_min_deg", "el_max_deg"}),
                setup);
  az_defaults.min_deg = setup.station.az_range.min_deg;
  az_defaults.max_deg = setup.station.az_range.max_deg;
  el_defaults.min_deg = setup.station.el_range.min_deg;
  el_defaults.max_deg = setup.station.el_range.max_deg;
  setup.az_plant = read_plant(sim_section.child("az", plant_keys), config.mount.az, az_defaults);
  setup.el_plant = read_plant(sim_section.child("el", plant_keys), config.mount.el, el_defaults);
  read_plant_fault(sim_section.child("az", plant_keys), true, setup);
  read_plant_fault(sim_section.child("el", plant_keys), false, setup);
  read_link(sim_section, setup);
  const ConfigSection control =
      file.section("control", {"window_deg", "ramp_s", "tracking_speed", "fast_zone_deg", "lead",
                               "tick_hz", "out_of_range", "park_az_deg", "park_el_deg"});
  read_out_of_range(control, setup);
  setup.station.az_control = control_for(control, config.mount.az);
  setup.station.el_control = control_for(control, config.mount.el);
  setup.station.az_supervisor = supervisor_for(config.mount.az);
  setup.station.el_supervisor = supervisor_for(config.mount.el);
  const double tick_hz = control.number("tick_hz").value_or(20.0);
  if (tick_hz < 1.0 || tick_hz > 200.0) control.fail("tick_hz", "must be 1 to 200");
  setup.station.tick_s = 1.0 / tick_hz;
  // R01: motors off within 200 ms of the last valid reading. A silence is noticed at a tick, up
  // to one tick after it passes the threshold, so the threshold leaves room for one tick.
  setup.station.az_supervisor.stale_s = std::max(0.1, 0.2 - setup.station.tick_s);
  setup.station.el_supervisor.stale_s = setup.station.az_supervisor.stale_s;
  setup.station.corrections =
      read_corrections(file.section("corrections", {"az_offset_deg", "el_offset_deg", "az_user_deg",
                                                    "el_user_deg", "tilt_el_deg"}));
  return config;
}

}  // namespace azt::app
