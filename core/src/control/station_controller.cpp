#include "azt/control/station_controller.hpp"

#include <algorithm>
#include <cmath>

namespace azt::control {
namespace {

/// Readings may lie a little past the travel (a shaft coasting past the soft limit at a stop):
/// they are still placed on the side the mount is on, never across the whole turn.
AzimuthRange reading_range(const AzimuthRange& travel) {
  constexpr double kOvertravelDeg = 20.0;
  return AzimuthRange{travel.min_deg - kOvertravelDeg, travel.max_deg + kOvertravelDeg};
}

}  // namespace

StationController::StationController(const StationControlConfig& config, AzEl start_mount)
    : config_(config),
      az_(config.az_control, config.az_supervisor, config.az_drive, start_mount.az_deg,
          config.tick_s),
      el_(config.el_control, config.el_supervisor, config.el_drive,
          config.el_fixed_deg.value_or(start_mount.el_deg), config.tick_s) {}

void StationController::on_encoder_reading(double now_s, double az_deg, double el_deg) {
  // A fixed elevation is known, not read: the tilt correction still sees the angle it is at.
  if (config_.el_fixed_deg) el_deg = *config_.el_fixed_deg;
  last_encoder_ = AzEl{az_deg, el_deg};
  const CorrectedPosition corrected = apply_corrections(az_deg, el_deg, corrections_);
  // An absolute sensor keeps its turn: only the corrections' (small) shift is added.
  const double az_mount =
      config_.az_absolute
          ? az_deg + std::remainder(corrected.az_deg - az_deg, 360.0)
          : plan_azimuth(az_.mount_deg(), corrected.az_deg, reading_range(config_.az_range));
  const double el_mount = corrected.el_deg > 270.0 ? corrected.el_deg - 360.0 : corrected.el_deg;
  // A pulse-counted axis reads its own count (on_pulse_edges()).
  if (!az_.pulses()) az_.on_reading(now_s, az_mount);
  if (!el_fixed() && !el_.pulses()) el_.on_reading(now_s, el_mount);
}

void StationController::on_pulse_edges(double now_s, std::size_t axis,
                                       std::span<const ports::PulseEdge> edges) {
  if (axis == 0) {
    az_.on_pulse_edges(now_s, edges);
  } else if (!el_fixed()) {
    el_.on_pulse_edges(now_s, edges);
  }
}

std::optional<std::string> StationController::home(double now_s, std::size_t axis,
                                                   bool home_closed) {
  if (axis != 0 && el_fixed()) return std::string{"the elevation is fixed: nothing to home"};
  return (axis == 0 ? az_ : el_).home(now_s, home_closed);
}

void StationController::stop_homing(double now_s, std::string_view reason) {
  az_.stop_homing(now_s, reason);
  if (!el_fixed()) el_.stop_homing(now_s, reason);
}

const PulseAxis* StationController::pulses(std::size_t axis) const {
  if (axis != 0 && el_fixed()) return nullptr;
  return (axis == 0 ? az_ : el_).pulses();
}

void StationController::set_corrections(const PositionCorrections& corrections) {
  if (last_encoder_) {
    const auto before =
        apply_corrections(last_encoder_->az_deg, last_encoder_->el_deg, corrections_);
    const auto after = apply_corrections(last_encoder_->az_deg, last_encoder_->el_deg, corrections);
    // The shortest way round: an azimuth change never adds a turn of cable wrap.
    const double az_delta = std::remainder(after.az_deg - before.az_deg, 360.0);
    const double el_delta = after.el_deg - before.el_deg;
    az_.rebase(az_delta);
    if (!el_fixed()) el_.rebase(el_delta);
  }
  corrections_ = corrections;
}

std::optional<double> StationController::jog_target(JogGoal& jog, const DrivenAxis& axis,
                                                    int direction, double speed,
                                                    const AxisTravel& travel,
                                                    double& rate_deg_s) const {
  rate_deg_s = 0.0;
  if (direction == 0) {
    jog = JogGoal{};
    return std::nullopt;
  }
  // At full speed the goal is the end of the travel: the controller runs flat out and its
  // deceleration zone stops the axis there if nobody stops it first.
  if (speed >= 1.0) {
    jog = JogGoal{direction, 0.0};
    return direction > 0 ? travel.max_deg : travel.min_deg;
  }
  // Slower (a game pad's stick half way): a goal that leaves where the axis stands and moves at
  // the asked fraction of the axis's full rate, tracked as a moving target with its rate fed
  // forward. A PWM axis then runs at that speed; a relay axis, with one speed, moves in steps
  // of its window that average it.
  if (jog.direction != direction) jog = JogGoal{direction, axis.mount_deg()};
  rate_deg_s = direction * speed * axis.control_config().max_rate_deg_s;
  jog.goal_deg =
      std::clamp(jog.goal_deg + rate_deg_s * config_.tick_s, travel.min_deg, travel.max_deg);
  return jog.goal_deg;
}

Duties StationController::tick(double now_s, const Demand& demand, const AzEl& rate_deg_s) {
  std::optional<double> az_target;
  std::optional<double> el_target;
  AzEl rate = rate_deg_s;
  if (!demand.jog) {
    az_jog_ = JogGoal{};
    el_jog_ = JogGoal{};
  }
  if (demand.position && demand.mount) {
    // A planned mount position: only ever clamped into the travel, as a last line of defence.
    az_target =
        std::clamp(demand.position->az_deg, config_.az_range.min_deg, config_.az_range.max_deg);
    el_target = plan_elevation(demand.position->el_deg, config_.el_range);
  } else if (demand.position) {
    az_target = plan_azimuth(az_.mount_deg(), demand.position->az_deg, config_.az_range);
    el_target = plan_elevation(demand.position->el_deg, config_.el_range);
  } else if (demand.test && !demand.test->azimuth && el_fixed()) {
    az_.drive(now_s, std::nullopt, 0.0);  // no elevation to test: nothing moves
    return duties();
  } else if (demand.test) {
    DrivenAxis& tested = demand.test->azimuth ? az_ : el_;
    (demand.test->azimuth ? el_ : az_).drive(now_s, std::nullopt, 0.0);
    tested.drive_test(now_s, demand.test->direction > 0 ? 1 : -1);
    return duties();
  } else if (demand.jog) {
    az_target =
        jog_target(az_jog_, az_, demand.jog->az, demand.jog->az_speed,
                   AxisTravel{config_.az_range.min_deg, config_.az_range.max_deg}, rate.az_deg);
    el_target =
        jog_target(el_jog_, el_, demand.jog->el, demand.jog->el_speed,
                   AxisTravel{config_.el_range.min_deg, config_.el_range.max_deg}, rate.el_deg);
  }
  az_.drive(now_s, az_target, rate.az_deg);
  // A fixed elevation is never driven: whatever angle a demand names, only azimuth moves.
  if (!el_fixed()) el_.drive(now_s, el_target, rate.el_deg);
  return duties();
}

Duties StationController::duties() const {
  return Duties{az_.duty(), el_.duty(), az_.setpoint_deg(), el_.setpoint_deg()};
}

Duties StationController::set_limits(const LimitSwitches& limits) {
  limits_ = limits;
  az_.set_limits(LimitPair{limits.az_ccw, limits.az_cw});
  if (!el_fixed()) el_.set_limits(LimitPair{limits.el_down, limits.el_up});
  return duties();
}

std::optional<AzEl> StationController::sky_position(double now_s) const {
  if (faulted() || az_.stale(now_s) || (!el_fixed() && el_.stale(now_s))) return std::nullopt;
  // A pulse-counted axis not homed knows how far it moved, not where it points.
  for (std::size_t i = 0; i < 2; ++i) {
    if (const PulseAxis* p = pulses(i); p && !p->homed()) return std::nullopt;
  }
  // Past the zenith on a flip mount the beam looks the other way: (az + 180, 180 − el).
  if (el_.mount_deg() > 90.0) {
    return AzEl{wrap_360(az_.mount_deg() + 180.0), 180.0 - el_.mount_deg()};
  }
  return AzEl{wrap_360(az_.mount_deg()), el_.mount_deg()};
}

bool StationController::faulted() const { return az_.faulted() || (!el_fixed() && el_.faulted()); }

void StationController::emergency_stop(double now_s, std::string_view reason) {
  az_.emergency_stop(now_s, reason);
  if (!el_fixed()) el_.emergency_stop(now_s, reason);
}

void StationController::clear_faults() {
  az_.clear_faults();
  el_.clear_faults();
}

void StationController::on_motor_readings(double now_s, const MotorReadings& az,
                                          const MotorReadings& el) {
  az_.on_motor_readings(now_s, az);
  el_.on_motor_readings(now_s, el);
}

}  // namespace azt::control
