#include "config/station_setup_config.hpp"

#include <algorithm>
#include <vector>

#include "azt/control/corrections.hpp"
#include "azt/proto/hub_frame.hpp"
#include "config/config_file.hpp"
#include "config/pointing_config.hpp"

namespace azt::app {
namespace {

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

void read_geometry(const ConfigSection& g, control::StationSetup& station) {
  auto az = control::AzimuthRange::make(g.number("az_min_deg").value_or(0.0),
                                        g.number("az_max_deg").value_or(360.0));
  if (!az) g.fail("az_min_deg", az.error().message);
  auto el = control::ElevationRange::make(g.number("el_min_deg").value_or(0.0),
                                          g.number("el_max_deg").value_or(90.0));
  if (!el) g.fail("el_min_deg", el.error().message);
  station.az_range = *az;
  station.el_range = *el;
}

/// `[control] out_of_range = "hold" | "park"`, with the park position `park_az_deg`,
/// `park_el_deg` (default: south at the lowest elevation).
void read_out_of_range(const ConfigSection& c, control::StationSetup& station) {
  if (c.text("out_of_range").value_or("hold") != "park") return;
  const control::AzEl park{c.number("park_az_deg").value_or(180.0),
                           c.number("park_el_deg").value_or(station.el_range.min_deg)};
  if (!control::plan_elevation(park.el_deg, station.el_range)) {
    c.fail("park_el_deg", "must be inside [geometry] el_min_deg..el_max_deg");
  }
  station.park_when_out_of_range = park;
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
    std::vector<double> entries;  // 60 numbers (the schema)
    for (const auto& node : *tilt) entries.push_back(node.value_or(0.0));
    auto table = control::TiltTable::make(entries);
    if (!table) s.fail("tilt_el_deg", table.error().message);
    c.tilt = *table;
  }
  return c;
}

/// [mount.pol] as the controller's pol axis: the [control] settings but its own window, the
/// travel checked.
control::PolAxisConfig pol_axis_for(const ConfigSection& c, const ConfigSection& m,
                                    const PolMount& mount, double stale_s) {
  control::PolAxisConfig pol;
  pol.control = control_for(c, mount.axis);
  pol.control.window_deg = mount.window_deg;
  pol.supervisor = supervisor_for(mount.axis);
  pol.supervisor.stale_s = stale_s;
  auto travel = control::PolTravel::make(mount.min_deg, mount.max_deg);
  if (!travel) m.fail("min_deg", travel.error().message);
  pol.travel = *travel;
  pol.start_mount_deg = std::clamp(0.0, mount.min_deg, mount.max_deg);
  return pol;
}

}  // namespace

control::StationSetup station_setup_from(const ConfigFile& file, const MountConfig& mount) {
  control::StationSetup station;
  read_geometry(file.section("geometry"), station);
  const ConfigSection control = file.section("control");
  read_out_of_range(control, station);
  station.az_control = control_for(control, mount.az);
  station.el_control = control_for(control, mount.el);
  station.az_supervisor = supervisor_for(mount.az);
  station.el_supervisor = supervisor_for(mount.el);
  const double tick_hz = control.number("tick_hz").value_or(20.0);  // 1 to 200 (the schema)
  station.tick_s = 1.0 / tick_hz;
  // R01: motors off within 200 ms of the last valid reading. A silence is noticed at a tick, up
  // to one tick after it passes the threshold, so the threshold leaves room for one tick.
  station.az_supervisor.stale_s = std::max(0.1, 0.2 - station.tick_s);
  station.el_supervisor.stale_s = station.az_supervisor.stale_s;
  if (mount.pol) {
    station.pol = pol_axis_for(control, file.section("mount").child("pol"), *mount.pol,
                               station.az_supervisor.stale_s);
  }
  if (mount.el_fixed) station.el_fixed_deg = mount.el_fixed->el_deg;
  station.corrections = read_corrections(file.section("corrections"));
  station.corrections.model = station_pointing_from(file);
  return station;
}

}  // namespace azt::app
