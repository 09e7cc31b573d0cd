#include "azt/sim/pass_sim.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "azt/control/station_controller.hpp"
#include "azt/sim/axis_plant.hpp"
#include "azt/util/angles.hpp"

namespace azt::sim {
namespace {
constexpr double kEarthKm = 6371.0;
constexpr double kMuKm3S2 = 398600.4418;

using V3 = std::array<double, 3>;  // east, north, up

/// The sky direction of the satellite at arc `theta` from its nearest point.
track::SkyPoint look(const SyntheticPass& p, double t, double theta) {
  const double d = p.offset_deg * kRadPerDeg;
  const double a = p.nearest_az_deg * kRadPerDeg;
  // Unit vectors from the Earth's centre, in the site's east/north/up axes.
  const V3 c{std::sin(d) * std::sin(a), std::sin(d) * std::cos(a), std::cos(d)};
  // Along the track, perpendicular to the site–nearest-point plane: azimuth a + 90° when
  // clockwise (the same at every offset, overhead included).
  const double sign = p.clockwise ? 1.0 : -1.0;
  const V3 along{sign * std::cos(a), -sign * std::sin(a), 0.0};
  const double r = kEarthKm + p.altitude_km;
  const V3 s{r * (std::cos(theta) * c[0] + std::sin(theta) * along[0]),
             r * (std::cos(theta) * c[1] + std::sin(theta) * along[1]),
             r * (std::cos(theta) * c[2] + std::sin(theta) * along[2])};
  const V3 rho{s[0], s[1], s[2] - kEarthKm};
  const double range = std::sqrt(rho[0] * rho[0] + rho[1] * rho[1] + rho[2] * rho[2]);
  double az = std::atan2(rho[0], rho[1]) / kRadPerDeg;
  if (az < 0.0) az += 360.0;
  return {t, az, std::asin(rho[2] / range) / kRadPerDeg};
}

}  // namespace

double synthetic_max_el_deg(double altitude_km, double offset_deg) {
  const double d = offset_deg * kRadPerDeg;
  const double ratio = kEarthKm / (kEarthKm + altitude_km);
  return std::atan2(std::cos(d) - ratio, std::sin(d)) / kRadPerDeg;
}

std::vector<track::SkyPoint> synthetic_pass(const SyntheticPass& p) {
  const double r = kEarthKm + p.altitude_km;
  const double rate = std::sqrt(kMuKm3S2 / (r * r * r));  // rad/s along the orbit
  // Visible while the arc from the site is below acos(R / r) (spherical horizon).
  const double horizon = std::acos(kEarthKm / r);
  const double d = p.offset_deg * kRadPerDeg;
  if (d >= horizon) return {};
  const double half = std::acos(std::cos(horizon) / std::cos(d));  // arc from nearest to horizon
  std::vector<track::SkyPoint> out;
  const double t_half = half / rate;
  const auto steps = static_cast<long>(std::floor(2.0 * t_half / p.step_s));
  for (long i = 0; i <= steps; ++i) {
    const double t = -t_half + static_cast<double>(i) * p.step_s;
    const track::SkyPoint s = look(p, t, t * rate);
    if (s.el_deg >= 0.0) out.push_back(s);
  }
  return out;
}

track::MountGeometry mount_geometry(const StationSimSetup& setup) {
  track::MountGeometry m;
  m.az = setup.station.az_range;
  m.el = setup.station.el_range;
  m.max_az_rate_deg_s = setup.plant.az.max_rate_deg_s;
  m.max_el_rate_deg_s = setup.plant.el.max_rate_deg_s;
  m.ramp_s = setup.station.az_control.ramp_s + setup.station.az_control.time_constant_s;
  return m;
}

Result<PassSimResult> simulate_pass(const std::vector<track::SkyPoint>& sky,
                                    const track::MountGeometry& mount, const StationSimSetup& setup,
                                    control::AzEl start, double prep_s) {
  auto plan = track::plan_pass(sky, mount, start.az_deg);
  if (!plan) return plan.error();
  StationSimSetup s = setup;
  s.station.az_range = mount.az;
  s.station.el_range = mount.el;
  s.plant.az.start_deg = start.az_deg;
  s.plant.el.start_deg = start.el_deg;
  s.plant.az.min_deg = mount.az.min_deg - 5.0;
  s.plant.az.max_deg = mount.az.max_deg + 5.0;
  s.plant.el.min_deg = mount.el.min_deg - 5.0;
  s.plant.el.max_deg = mount.el.max_deg + 5.0;
  control::StationController station(station_control_config(s), start);
  AxisPlant az(s.plant.az);
  AxisPlant el(s.plant.el);

  PassSimResult out;
  out.flip = plan.value().flip;
  out.planned_max_error_deg = plan.value().max_error_deg;
  out.planned_loss_s = plan.value().loss_s;
  const auto& track = plan.value().track;
  for (std::size_t i = 1; i < track.size(); ++i) {
    out.pass_span_deg += std::fabs(track[i].az_deg - track[i - 1].az_deg);
  }
  const double aos = sky.front().t_s;
  const double los = sky.back().t_s;
  const double dt = s.station.tick_s;
  double sum_sq = 0.0;
  std::size_t n = 0;
  std::size_t k = 0;  // the sky sample at or before t
  std::optional<double> last_demand_az;
  double last_shaft_az = az.shaft_deg();
  const auto ticks = static_cast<long>(std::floor((los - aos + prep_s) / dt));
  for (long tick = 0; tick <= ticks; ++tick) {
    const double t = aos - prep_s + static_cast<double>(tick) * dt;
    // The plants' encoders read perfectly here; the hub, noise and faults are station_sim's.
    station.on_encoder_reading(t, control::wrap_360(az.shaft_deg()), el.shaft_deg());
    const track::MountPoint want = plan.value().at(t);
    const track::MountPoint ahead = plan.value().at(t + 1.0);
    control::Demand demand;
    demand.position = control::AzEl{want.az_deg, want.el_deg};
    demand.mount = true;
    const control::AzEl rate{t < aos ? 0.0 : ahead.az_deg - want.az_deg,
                             t < aos ? 0.0 : ahead.el_deg - want.el_deg};
    if (last_demand_az && std::fabs(want.az_deg - *last_demand_az) >= 180.0) ++out.unwinds;
    last_demand_az = want.az_deg;
    const control::Duties d = station.tick(t, demand, rate);
    az.step(d.az, dt);
    el.step(d.el, dt);
    if (t < aos) {
      last_shaft_az = az.shaft_deg();
      continue;
    }
    out.az_travel_deg += std::fabs(az.shaft_deg() - last_shaft_az);
    last_shaft_az = az.shaft_deg();
    while (k + 1 < sky.size() && sky[k + 1].t_s <= t) ++k;
    const double f = k + 1 < sky.size() ? (t - sky[k].t_s) / (sky[k + 1].t_s - sky[k].t_s) : 0.0;
    const double sat_az =
        sky[k].az_deg +
        (k + 1 < sky.size() ? f * std::remainder(sky[k + 1].az_deg - sky[k].az_deg, 360.0) : 0.0);
    const double sat_el =
        sky[k].el_deg + (k + 1 < sky.size() ? f * (sky[k + 1].el_deg - sky[k].el_deg) : 0.0);
    const track::SkyPoint beam = track::mount_to_sky({t, az.shaft_deg(), el.shaft_deg()});
    const track::SkyPoint planned = track::mount_to_sky(want);
    const double err = track::separation_deg(beam.az_deg, beam.el_deg, sat_az, sat_el);
    const double accepted = track::separation_deg(planned.az_deg, planned.el_deg, sat_az, sat_el);
    out.max_error_deg = std::max(out.max_error_deg, err);
    out.max_excess_deg = std::max(out.max_excess_deg, err - accepted);
    if (err > mount.loss_error_deg) out.loss_s += dt;
    sum_sq += err * err;
    ++n;
  }
  out.rms_error_deg = n > 0 ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0;
  if (station.faulted()) {
    for (const auto& [name, axis] : {std::pair{"az", station.az()}, {"el", station.el()}}) {
      if (axis.fault != control::FaultKind::None)
        out.faults.push_back(std::string(name) + ": " + axis.reason);
    }
  }
  return out;
}

}  // namespace azt::sim
