// The real controllers and supervisors driving simulated plants through a simulated EncoderHub
// link, in virtual time: readings travel as encoded frames (with injected loss and corruption)
// through the same decoder the daemon uses.
#include "azt/sim/station_sim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

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

/// One axis: its plant, controller and supervisor, and what the loop knows of it.
struct Axis {
  AxisPlant plant;
  control::AxisController controller;
  control::AxisSupervisor supervisor;
  double mount_deg = 0.0;  ///< last accepted reading, in mount degrees
  bool fault_reported = false;

  Axis(const AxisParams& p, control::AxisControlConfig c, control::SupervisorConfig s)
      : plant(p),
        controller((c.lsb_deg = lsb_deg(p), c)),
        supervisor((s.lsb_deg = lsb_deg(p), s)) {}
};

class StationLoop {
 public:
  explicit StationLoop(const StationSimSetup& setup)
      : setup_(setup),
        az_(setup.az_plant, setup.az_control, setup.az_supervisor),
        el_(setup.el_plant, setup.el_control, setup.el_supervisor),
        decoder_(accept_for(setup.frame_version)),
        rng_(setup.seed) {
    az_.mount_deg = setup.az_plant.start_deg;
    el_.mount_deg = setup.el_plant.start_deg;
  }

  /// One control tick at `t_s`: read the hub, drive both axes towards `demand` (nullopt: hold).
  void tick(double t_s, const std::optional<AzEl>& demand, const AzEl& rate_deg_s) {
    inject_due_faults(t_s);
    transmit_frame(t_s);
    drive(az_, t_s,
          demand
              ? std::optional(control::plan_azimuth(az_.mount_deg, demand->az_deg, setup_.az_range))
              : std::nullopt,
          rate_deg_s.az_deg);
    drive(el_, t_s,
          demand ? control::plan_elevation(demand->el_deg, setup_.el_range) : std::nullopt,
          rate_deg_s.el_deg);
    for (const Axis* axis : {&az_, &el_}) {
      if (axis->supervisor.fault() != control::FaultKind::None) {
        max_duty_after_fault_ = std::max(max_duty_after_fault_, std::fabs(axis->controller.duty()));
      }
    }
    const double dt = setup_.tick_s / setup_.plant_substeps;
    for (int i = 0; i < setup_.plant_substeps; ++i) {
      az_.plant.step(az_.controller.duty(), dt);
      el_.plant.step(el_.controller.duty(), dt);
    }
  }

  [[nodiscard]] double max_duty_after_fault() const { return max_duty_after_fault_; }
  Axis& az() { return az_; }
  Axis& el() { return el_; }
  [[nodiscard]] const proto::HubDecoder& decoder() const { return decoder_; }

  void collect_faults(std::vector<std::string>& out, double t_s) {
    for (auto* axis : {&az_, &el_}) {
      const auto kind = axis->supervisor.fault();
      if (kind != control::FaultKind::None && !axis->fault_reported) {
        axis->fault_reported = true;
        out.push_back(std::string(axis == &az_ ? "az" : "el") + ": " +
                      std::string(control::to_string(kind)) + " at " + std::to_string(t_s) +
                      " s: " + axis->supervisor.reason());
      }
    }
  }

 private:
  void inject_due_faults(double t_s) {
    for (; next_fault_ < setup_.plant_faults.size() && setup_.plant_faults[next_fault_].at_s <= t_s;
         ++next_fault_) {
      const ScheduledFault& f = setup_.plant_faults[next_fault_];
      (f.azimuth ? az_ : el_).plant.inject(f.fault);
    }
  }

  static proto::HubAccept accept_for(proto::HubFrameVersion v) {
    return v == proto::HubFrameVersion::Crc8 ? proto::HubAccept::Crc8Only
                                             : proto::HubAccept::SeedOnly;
  }

  void transmit_frame(double t_s) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    if (!link_started_) {
      // Our hub firmware sends a delimiter at boot, so the first frame is not taken for the tail
      // of an earlier one.
      proto::HubFrame unused{};
      decoder_.push(0x00, unused);
      link_started_ = true;
    }
    if (u(rng_) < setup_.link.frame_loss) return;
    const proto::HubReading reading{az_.plant.encoder_bits(), el_.plant.encoder_bits(),
                                    az_.plant.encoder_raw(), el_.plant.encoder_raw()};
    std::array<std::uint8_t, proto::kHubMaxFrameBytes> frame{};
    const std::size_t n =
        proto::encode_hub_frame(reading, setup_.frame_version, frame.data(), frame.size());
    for (std::size_t i = 0; i < n; ++i) {
      std::uint8_t byte = frame[i];
      if (u(rng_) < setup_.link.byte_corruption) byte = static_cast<std::uint8_t>(rng_() & 0xFF);
      proto::HubFrame decoded{};
      if (decoder_.push(byte, decoded) == proto::HubFrameStatus::Ok) accept(t_s, decoded.reading);
    }
  }

  void accept(double t_s, const proto::HubReading& r) {
    const double az_deg = proto::hub_raw_to_deg(r.az_raw, r.az_bits);
    const double el_deg = proto::hub_raw_to_deg(r.el_raw, r.el_bits);
    // The encoder turns once per revolution: the mount angle is the equivalent nearest the last
    // one (overlap rotators). Elevation encoders read 0–360 too: above 180 is below the horizon.
    const double az_mount = control::plan_azimuth(az_.mount_deg, az_deg, setup_.az_range);
    const double el_mount = el_deg > 270.0 ? el_deg - 360.0 : el_deg;
    if (az_.supervisor.on_reading(t_s, az_mount)) az_.mount_deg = az_mount;
    if (el_.supervisor.on_reading(t_s, el_mount)) el_.mount_deg = el_mount;
  }

  void drive(Axis& axis, double t_s, std::optional<double> target_deg, double rate_deg_s) const {
    if (!target_deg) {
      // Holding: let any move finish its soft stop at the present position.
      target_deg = axis.mount_deg;
      rate_deg_s = 0.0;
    }
    const double duty =
        axis.controller.update(*target_deg, axis.mount_deg, rate_deg_s, setup_.tick_s);
    const auto verdict = axis.supervisor.check(t_s, duty, *target_deg - axis.mount_deg);
    if (!verdict.allow_motion) axis.controller.halt();
  }

  const StationSimSetup& setup_;
  Axis az_;
  Axis el_;
  proto::HubDecoder decoder_;
  std::mt19937_64 rng_;
  bool link_started_ = false;
  std::size_t next_fault_ = 0;  ///< plant_faults are sorted by time
  double max_duty_after_fault_ = 0.0;
};

AxisMetrics finish_axis(const Accumulator& acc, const Axis& axis, double hours, double travel) {
  AxisMetrics m;
  m.rms_error_deg = acc.rms();
  m.max_error_deg = acc.max_abs;
  m.starts = axis.controller.starts();
  m.starts_per_hour = hours > 0.0 ? static_cast<double>(m.starts) / hours : 0.0;
  m.travel_deg = travel;
  return m;
}

}  // namespace

SimResult simulate_tracking(const StationSimSetup& setup, const SkyTrack& sky, double duration_s) {
  StationLoop loop(setup);
  SimResult result;
  Accumulator az_err, el_err;
  double tracked_s = 0.0, az_travel = 0.0, el_travel = 0.0;
  std::optional<AzEl> previous;
  const double l2_slack = 2.0;  // acquisition: both axes within window + 2 LSB
  const std::uint64_t ticks = static_cast<std::uint64_t>(std::llround(duration_s / setup.tick_s));
  for (std::uint64_t k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) * setup.tick_s;
    std::optional<AzEl> target = sky(t);
    if (target && !control::plan_elevation(target->el_deg, setup.el_range)) target.reset();
    AzEl rate{};
    if (target) {
      if (const auto ahead = sky(t + 1.0)) {
        rate =
            AzEl{wrapped_difference(ahead->az_deg, target->az_deg), ahead->el_deg - target->el_deg};
      }
    }
    // Out of range: hold where the antenna is, or drive to the park position.
    loop.tick(t, target ? target : setup.park_when_out_of_range, rate);
    loop.collect_faults(result.faults, t);
    if (!target) {
      previous.reset();
      continue;
    }
    const double e_az = wrapped_difference(target->az_deg, loop.az().plant.shaft_deg());
    const double e_el = target->el_deg - loop.el().plant.shaft_deg();
    if (!result.acquired_s) {
      const double az_ok = setup.az_control.window_deg + l2_slack * lsb_deg(setup.az_plant);
      const double el_ok = setup.el_control.window_deg + l2_slack * lsb_deg(setup.el_plant);
      if (std::fabs(e_az) <= az_ok && std::fabs(e_el) <= el_ok) result.acquired_s = t;
    }
    if (result.acquired_s) {
      az_err.add(e_az);
      el_err.add(e_el);
      tracked_s += setup.tick_s;
      if (previous) {
        az_travel += std::fabs(wrapped_difference(target->az_deg, previous->az_deg));
        el_travel += std::fabs(target->el_deg - previous->el_deg);
      }
      previous = target;
    }
  }
  const double hours = tracked_s / 3600.0;
  result.az = finish_axis(az_err, loop.az(), hours, az_travel);
  result.el = finish_axis(el_err, loop.el(), hours, el_travel);
  Accumulator pooled{az_err.sum_sq + el_err.sum_sq, std::max(az_err.max_abs, el_err.max_abs),
                     az_err.n + el_err.n};
  result.rms_error_deg = pooled.rms();
  result.max_error_deg = pooled.max_abs;
  result.simulated_s = static_cast<double>(ticks) * setup.tick_s;
  result.hub = loop.decoder().counters();
  result.max_duty_after_fault = loop.max_duty_after_fault();
  result.final_position = {control::wrap_360(loop.az().plant.shaft_deg()),
                           loop.el().plant.shaft_deg()};
  return result;
}

SimResult simulate_slew(const StationSimSetup& setup, AzEl to, double max_duration_s) {
  StationLoop loop(setup);
  SimResult result;
  const double az_target =
      control::plan_azimuth(setup.az_plant.start_deg, to.az_deg, setup.az_range);
  const double az_dir = az_target >= setup.az_plant.start_deg ? 1.0 : -1.0;
  const double el_dir = to.el_deg >= setup.el_plant.start_deg ? 1.0 : -1.0;
  result.slew_min_time_s =
      std::max(std::fabs(az_target - setup.az_plant.start_deg) / setup.az_plant.max_rate_deg_s,
               std::fabs(to.el_deg - setup.el_plant.start_deg) / setup.el_plant.max_rate_deg_s);
  double rest_since = -1.0;
  const std::uint64_t ticks =
      static_cast<std::uint64_t>(std::llround(max_duration_s / setup.tick_s));
  std::uint64_t k = 0;
  for (; k < ticks; ++k) {
    const double t = static_cast<double>(k) * setup.tick_s;
    loop.tick(t, to, AzEl{});
    loop.collect_faults(result.faults, t);
    const double az_shaft =
        control::plan_azimuth(az_target, loop.az().plant.shaft_deg(), setup.az_range);
    result.az.overshoot_deg = std::max(result.az.overshoot_deg, (az_shaft - az_target) * az_dir);
    result.el.overshoot_deg =
        std::max(result.el.overshoot_deg, (loop.el().plant.shaft_deg() - to.el_deg) * el_dir);
    const bool at_rest = !loop.az().controller.moving() && !loop.el().controller.moving() &&
                         std::fabs(loop.az().plant.motor_rate_deg_s()) < 1e-3 &&
                         std::fabs(loop.el().plant.motor_rate_deg_s()) < 1e-3 && t > 0.0;
    if (at_rest && rest_since < 0.0) rest_since = t;
    if (!at_rest) rest_since = -1.0;
    if (rest_since >= 0.0 && t - rest_since >= 2.0) break;  // settled for 2 s
  }
  if (rest_since >= 0.0) result.slew_time_s = rest_since;
  result.az.max_error_deg = std::fabs(wrapped_difference(to.az_deg, loop.az().plant.shaft_deg()));
  result.el.max_error_deg = std::fabs(to.el_deg - loop.el().plant.shaft_deg());
  result.max_error_deg = std::max(result.az.max_error_deg, result.el.max_error_deg);
  result.az.starts = loop.az().controller.starts();
  result.el.starts = loop.el().controller.starts();
  result.simulated_s = static_cast<double>(k) * setup.tick_s;
  result.hub = loop.decoder().counters();
  result.max_duty_after_fault = loop.max_duty_after_fault();
  result.final_position = {control::wrap_360(loop.az().plant.shaft_deg()),
                           loop.el().plant.shaft_deg()};
  return result;
}

}  // namespace azt::sim
