// The daemon's own station (control::PortedStation: the controllers and supervisors over the
// ports) driving simulated plants in virtual time: readings travel as encoded frames, from the
// hub model (with injected loss and corruption) or the hub firmware on a simulated AVR, through
// the same decoder the daemon uses.
#include "azt/sim/station_sim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "azt/sim/station_loop.hpp"

namespace azt::sim {
namespace {

using control::AzEl;

double lsb_deg(const AxisParams& p) { return proto::hub_resolution_deg(p.encoder_bits); }

/// Signed difference a − b wrapped to [−180, 180).
double wrapped_difference(double a_deg, double b_deg) {
  return control::wrap_360(a_deg - b_deg + 180.0) - 180.0;
}

struct Accumulator {
  double sum_sq = 0.0;
  double max_abs = 0.0;
  std::uint64_t n = 0;
  void add(double x) {
    sum_sq += x * x;
    max_abs = std::max(max_abs, std::fabs(x));
    ++n;
  }
  [[nodiscard]] double rms() const {
    return n == 0 ? 0.0 : std::sqrt(sum_sq / static_cast<double>(n));
  }
};

AxisMetrics finish_axis(const Accumulator& acc, std::uint64_t starts, double hours, double travel) {
  AxisMetrics m;
  m.rms_error_deg = acc.rms();
  m.max_error_deg = acc.max_abs;
  m.starts = starts;
  m.starts_per_hour = hours > 0.0 ? static_cast<double>(m.starts) / hours : 0.0;
  m.travel_deg = travel;
  return m;
}

/// The polarisation axis through a run (PolTracking): its demand each tick and its errors.
class PolMeter {
 public:
  PolMeter(const StationSimSetup& setup, const PolTracking& pol)
      : pol_(pol), active_(pol.track && setup.plant.pol && setup.station.pol) {
    if (active_) {
      acquire_deg_ = setup.station.pol->control.window_deg +
                     2.0 * proto::hub_resolution_deg(setup.plant.pol->encoder_bits);
    }
  }

  [[nodiscard]] control::PolDemand demand(double t_s) const {
    if (!active_) return {};
    control::PolDemand d{pol_.track(t_s), 0.0};
    const auto ahead = pol_.track(t_s + 1.0);
    if (d.feed_deg && ahead) d.rate_deg_s = control::fold_linear_deg(*ahead - *d.feed_deg);
    return d;
  }

  /// After the tick at `t_s` that was asked for `feed_deg`.
  void measure(double t_s, double tick_s, const StationLoop& loop, std::optional<double> feed_deg) {
    if (!active_ || !loop.pol()) return;
    // NaN while holding (a plain double: GCC 12 misreads two optionals compared here).
    const double target = loop.pol()->target_mount_deg().value_or(std::nan(""));
    if (std::fabs(target - last_target_deg_) > 1.0) settle_until_s_ = t_s + pol_.settle_s;
    last_target_deg_ = target;
    if (!feed_deg) return;
    if (pol_.reference) feed_deg = pol_.reference(t_s);
    if (!feed_deg) return;
    const double error = control::fold_linear_deg(*feed_deg - loop.pol_plant()->shaft_deg());
    if (!acquired_) acquired_ = std::fabs(error) <= acquire_deg_;
    if (!acquired_) return;
    if (t_s < settle_until_s_) {
      settling_s_ += tick_s;
      return;
    }
    errors_.add(error);
    counted_s_ += tick_s;
  }

  void finish(SimResult& result, const StationLoop& loop) const {
    if (!active_ || !loop.pol()) return;
    result.pol = finish_axis(errors_, loop.pol()->axis().starts(), counted_s_ / 3600.0, 0.0);
    result.pol_settling_s = settling_s_;
    result.pol_counted_s = counted_s_;
  }

 private:
  const PolTracking& pol_;
  bool active_;
  double acquire_deg_ = 0.0;
  bool acquired_ = false;
  double last_target_deg_ = std::nan("");
  double settle_until_s_ = -1.0;
  double settling_s_ = 0.0;
  double counted_s_ = 0.0;
  Accumulator errors_;
};

}  // namespace

control::StationControlConfig station_control_config(const StationSimSetup& setup) {
  control::StationControlConfig c = setup.station.control_config();
  // The simulated station reads the plants' encoders (the same as the mount's when the setup
  // comes from a configuration file; tests may give the plants other resolutions).
  c.az_control.lsb_deg = proto::hub_resolution_deg(setup.plant.az.encoder_bits);
  c.el_control.lsb_deg = proto::hub_resolution_deg(setup.plant.el.encoder_bits);
  // An actuator elevation: its step is a count of its reed (DrivenAxis takes it from the scale)
  // or of its pot's ADC at the coarse end of the stroke, as the hardware backend's.
  if (const auto& act = setup.plant.el_actuator) {
    if (const SimActuatorReed* reed = act->reed()) c.el_drive.pulses = reed->pulses;
    if (const control::PotInputConfig* pot = act->pot()) {
      c.el_drive.sensor_step_deg = pot->max_deg_per_count();
    }
  }
  if (c.pol && setup.plant.pol) {
    c.pol->control.lsb_deg = proto::hub_resolution_deg(setup.plant.pol->encoder_bits);
  }
  c.az_drive.brake = setup.motors[0].brake;
  c.az_drive.trips = setup.motors[0].trips;
  c.el_drive.brake = setup.motors[1].brake;
  c.el_drive.trips = setup.motors[1].trips;
  return c;
}

SimResult simulate_tracking(const StationSimSetup& setup, const SkyTrack& sky, double duration_s,
                            std::unique_ptr<SimulatedHub> hub, const PolTracking& pol) {
  StationLoop loop(setup, std::move(hub));
  PolMeter pol_meter(setup, pol);
  SimResult result;
  Accumulator az_err, el_err;
  double tracked_s = 0.0, az_travel = 0.0, el_travel = 0.0;
  std::optional<AzEl> previous;
  const double l2_slack = 2.0;  // acquisition: both axes within window + 2 LSB
  // A fixed elevation is not tracked: only azimuth's error counts.
  const bool el_driven = !setup.station.el_fixed_deg;
  const std::uint64_t ticks =
      static_cast<std::uint64_t>(std::llround(duration_s / setup.station.tick_s));
  for (std::uint64_t k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) * setup.station.tick_s;
    std::optional<AzEl> target = sky(t);
    if (target && !control::plan_elevation(target->el_deg, setup.station.el_range)) target.reset();
    AzEl rate{};
    if (target) {
      if (const auto ahead = sky(t + 1.0)) {
        rate =
            AzEl{wrapped_difference(ahead->az_deg, target->az_deg), ahead->el_deg - target->el_deg};
      }
    }
    // Out of range: hold where the antenna is, or drive to the park position.
    const control::PolDemand pol_demand = pol_meter.demand(t);
    loop.tick(t, target ? target : setup.station.park_when_out_of_range, rate, pol_demand);
    loop.collect_faults(result.faults, t);
    pol_meter.measure(t, setup.station.tick_s, loop, pol_demand.feed_deg);
    if (!target) {
      previous.reset();
      continue;
    }
    const double e_az = wrapped_difference(target->az_deg, loop.az_plant().shaft_deg());
    const double e_el = el_driven ? target->el_deg - loop.el_plant().shaft_deg() : 0.0;
    if (!result.acquired_s) {
      const double az_ok = setup.station.az_control.window_deg + l2_slack * lsb_deg(setup.plant.az);
      const double el_ok = setup.station.el_control.window_deg + l2_slack * lsb_deg(setup.plant.el);
      if (std::fabs(e_az) <= az_ok && std::fabs(e_el) <= el_ok) result.acquired_s = t;
    }
    if (result.acquired_s) {
      az_err.add(e_az);
      if (el_driven) el_err.add(e_el);
      tracked_s += setup.station.tick_s;
      if (previous) {
        az_travel += std::fabs(wrapped_difference(target->az_deg, previous->az_deg));
        if (el_driven) el_travel += std::fabs(target->el_deg - previous->el_deg);
      }
      previous = target;
    }
  }
  const double hours = tracked_s / 3600.0;
  result.az = finish_axis(az_err, loop.station().starts_az(), hours, az_travel);
  result.el = finish_axis(el_err, loop.station().starts_el(), hours, el_travel);
  Accumulator pooled{az_err.sum_sq + el_err.sum_sq, std::max(az_err.max_abs, el_err.max_abs),
                     az_err.n + el_err.n};
  result.rms_error_deg = pooled.rms();
  result.max_error_deg = pooled.max_abs;
  result.simulated_s = static_cast<double>(ticks) * setup.station.tick_s;
  result.hub = loop.hub_counters();
  result.max_duty_after_fault = loop.max_duty_after_fault();
  result.brake_pulled_against_s = loop.brake_pulled_against_s();
  result.final_position = {control::wrap_360(loop.az_plant().shaft_deg()),
                           loop.el_plant().shaft_deg()};
  pol_meter.finish(result, loop);
  return result;
}

SimResult simulate_slew(const StationSimSetup& setup, AzEl to, double max_duration_s,
                        std::unique_ptr<SimulatedHub> hub) {
  StationLoop loop(setup, std::move(hub));
  SimResult result;
  // A fixed elevation stays where it stands: the slew is azimuth's alone.
  if (setup.station.el_fixed_deg) to.el_deg = *setup.station.el_fixed_deg;
  const double az_target =
      control::plan_azimuth(setup.plant.az.start_deg, to.az_deg, setup.station.az_range);
  const double az_dir = az_target >= setup.plant.az.start_deg ? 1.0 : -1.0;
  const double el_dir = to.el_deg >= setup.plant.el.start_deg ? 1.0 : -1.0;
  result.slew_min_time_s =
      std::max(std::fabs(az_target - setup.plant.az.start_deg) / setup.plant.az.max_rate_deg_s,
               std::fabs(to.el_deg - setup.plant.el.start_deg) / setup.plant.el.max_rate_deg_s);
  double rest_since = -1.0;
  const std::uint64_t ticks =
      static_cast<std::uint64_t>(std::llround(max_duration_s / setup.station.tick_s));
  std::uint64_t k = 0;
  for (; k < ticks; ++k) {
    const double t = static_cast<double>(k) * setup.station.tick_s;
    loop.tick(t, to, AzEl{});
    loop.collect_faults(result.faults, t);
    const double az_shaft =
        control::plan_azimuth(az_target, loop.az_plant().shaft_deg(), setup.station.az_range);
    result.az.overshoot_deg = std::max(result.az.overshoot_deg, (az_shaft - az_target) * az_dir);
    result.el.overshoot_deg =
        std::max(result.el.overshoot_deg, (loop.el_plant().shaft_deg() - to.el_deg) * el_dir);
    const bool at_rest = !loop.station().az().moving && !loop.station().el().moving &&
                         std::fabs(loop.az_plant().motor_rate_deg_s()) < 1e-3 &&
                         std::fabs(loop.el_plant().motor_rate_deg_s()) < 1e-3 && t > 0.0;
    if (at_rest && rest_since < 0.0) rest_since = t;
    if (!at_rest) rest_since = -1.0;
    if (rest_since >= 0.0 && t - rest_since >= 2.0) break;  // settled for 2 s
  }
  if (rest_since >= 0.0) result.slew_time_s = rest_since;
  result.az.max_error_deg = std::fabs(wrapped_difference(to.az_deg, loop.az_plant().shaft_deg()));
  result.el.max_error_deg = std::fabs(to.el_deg - loop.el_plant().shaft_deg());
  result.max_error_deg = std::max(result.az.max_error_deg, result.el.max_error_deg);
  result.az.starts = loop.station().starts_az();
  result.el.starts = loop.station().starts_el();
  result.simulated_s = static_cast<double>(k) * setup.station.tick_s;
  result.hub = loop.hub_counters();
  result.max_duty_after_fault = loop.max_duty_after_fault();
  result.brake_pulled_against_s = loop.brake_pulled_against_s();
  result.final_position = {control::wrap_360(loop.az_plant().shaft_deg()),
                           loop.el_plant().shaft_deg()};
  return result;
}

}  // namespace azt::sim
