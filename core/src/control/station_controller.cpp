#include "azt/control/station_controller.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace azt::control {
namespace {

SupervisorConfig with_lsb(SupervisorConfig s, const AxisControlConfig& c) {
  s.lsb_deg = c.lsb_deg;
  return s;
}

double relay_duty(RelayCommand command) {
  switch (command) {
    case RelayCommand::Forward:
      return 1.0;
    case RelayCommand::Reverse:
      return -1.0;
    case RelayCommand::Off:
      break;
  }
  return 0.0;
}

/// Readings may lie a little past the travel (a shaft coasting past the soft limit at a stop):
/// they are still placed on the side the mount is on, never across the whole turn.
AzimuthRange reading_range(const AzimuthRange& travel) {
  constexpr double kOvertravelDeg = 20.0;
  return AzimuthRange{travel.min_deg - kOvertravelDeg, travel.max_deg + kOvertravelDeg};
}

}  // namespace

std::string_view to_string(DriveKind kind) {
  switch (kind) {
    case DriveKind::Pwm:
      return "pwm";
    case DriveKind::Relay:
      return "relay";
    case DriveKind::Setpoint:
      return "setpoint";
  }
  return "?";
}

bool sends_setpoint(DriveKind kind) {
  switch (kind) {
    case DriveKind::Pwm:
    case DriveKind::Relay:
      return false;
    case DriveKind::Setpoint:
      return true;
  }
  return false;
}

double StationController::Axis::duty() const {
  switch (drive.kind) {
    case DriveKind::Relay:
      return relay_duty(relay.command());
    case DriveKind::Setpoint:
      return setpoint_duty;
    case DriveKind::Pwm:
      break;
  }
  return controller.duty();
}

bool StationController::Axis::moving() const {
  switch (drive.kind) {
    case DriveKind::Pwm:
      return controller.moving();  // through its soft stop, while the duty winds down
    case DriveKind::Relay:
    case DriveKind::Setpoint:
      return duty() != 0.0;
  }
  return duty() != 0.0;
}

void StationController::Axis::halt(double now_s) {
  controller.halt();
  relay.halt(now_s);
  if (sends_setpoint(drive.kind)) {
    setpoint_deg = mount_deg;
    setpoint_duty = 0.0;
  }
}

StationController::StationController(const StationControlConfig& config, AzEl start_mount)
    : config_(config),
      az_{AxisController(config.az_control),
          AxisSupervisor(with_lsb(config.az_supervisor, config.az_control)),
          start_mount.az_deg,
          config.az_drive,
          RelayDrive(config.az_drive.relay),
          std::nullopt,
          0.0,
          false},
      el_{AxisController(config.el_control),
          AxisSupervisor(with_lsb(config.el_supervisor, config.el_control)),
          start_mount.el_deg,
          config.el_drive,
          RelayDrive(config.el_drive.relay),
          std::nullopt,
          0.0,
          false} {}

void StationController::on_encoder_reading(double now_s, double az_deg, double el_deg) {
  last_encoder_ = AzEl{az_deg, el_deg};
  const CorrectedPosition corrected = apply_corrections(az_deg, el_deg, corrections_);
  // An absolute sensor keeps its turn: only the corrections' (small) shift is added.
  const double az_mount =
      config_.az_absolute
          ? az_deg + std::remainder(corrected.az_deg - az_deg, 360.0)
          : plan_azimuth(az_.mount_deg, corrected.az_deg, reading_range(config_.az_range));
  const double el_mount = corrected.el_deg > 270.0 ? corrected.el_deg - 360.0 : corrected.el_deg;
  if (az_.supervisor.on_reading(now_s, az_mount)) az_.mount_deg = az_mount;
  if (el_.supervisor.on_reading(now_s, el_mount)) el_.mount_deg = el_mount;
}

void StationController::set_corrections(const PositionCorrections& corrections) {
  if (last_encoder_) {
    const auto before =
        apply_corrections(last_encoder_->az_deg, last_encoder_->el_deg, corrections_);
    const auto after = apply_corrections(last_encoder_->az_deg, last_encoder_->el_deg, corrections);
    // The shortest way round: an azimuth change never adds a turn of cable wrap.
    const double az_delta = std::remainder(after.az_deg - before.az_deg, 360.0);
    const double el_delta = after.el_deg - before.el_deg;
    az_.mount_deg += az_delta;
    el_.mount_deg += el_delta;
    az_.supervisor.rebase(az_delta);
    el_.supervisor.rebase(el_delta);
  }
  corrections_ = corrections;
}

std::optional<double> StationController::jog_target(int direction, bool azimuth) const {
  if (direction == 0) return std::nullopt;
  if (azimuth) return direction > 0 ? config_.az_range.max_deg : config_.az_range.min_deg;
  return direction > 0 ? config_.el_range.max_deg : config_.el_range.min_deg;
}

Duties StationController::tick(double now_s, const Demand& demand, const AzEl& rate_deg_s) {
  std::optional<double> az_target;
  std::optional<double> el_target;
  AzEl rate = rate_deg_s;
  if (demand.position && demand.mount) {
    // A planned mount position: only ever clamped into the travel, as a last line of defence.
    az_target =
        std::clamp(demand.position->az_deg, config_.az_range.min_deg, config_.az_range.max_deg);
    el_target = plan_elevation(demand.position->el_deg, config_.el_range);
  } else if (demand.position) {
    az_target = plan_azimuth(az_.mount_deg, demand.position->az_deg, config_.az_range);
    el_target = plan_elevation(demand.position->el_deg, config_.el_range);
  } else if (demand.test) {
    Axis& tested = demand.test->azimuth ? az_ : el_;
    drive(demand.test->azimuth ? el_ : az_, now_s, std::nullopt, 0.0);
    drive_test(tested, now_s, demand.test->direction > 0 ? 1 : -1);
    return duties();
  } else if (demand.jog) {
    // A continuous move runs to the end of the travel at full speed; the controller's
    // deceleration zone stops it there if nobody stops it first.
    az_target = jog_target(demand.jog->az, true);
    el_target = jog_target(demand.jog->el, false);
    rate = AzEl{};
  }
  drive(az_, now_s, az_target, rate.az_deg);
  drive(el_, now_s, el_target, rate.el_deg);
  return duties();
}

Duties StationController::duties() const {
  Duties d{az_.duty(), el_.duty(), std::nullopt, std::nullopt};
  if (sends_setpoint(az_.drive.kind)) d.az_setpoint_deg = az_.setpoint_deg;
  if (sends_setpoint(el_.drive.kind)) d.el_setpoint_deg = el_.setpoint_deg;
  return d;
}

double StationController::drive(Axis& axis, double now_s, std::optional<double> target_deg,
                                double rate_deg_s) const {
  if (!target_deg) {
    // Holding: a PWM move finishes its soft stop at the present position. A setpoint axis is
    // sent where it stands when the hold begins (a STOP mid-move stops the box there), then
    // keeps that setpoint: re-sending the moving reading every tick would chase the coast.
    const bool setpoint = sends_setpoint(axis.drive.kind);
    if (setpoint && (!axis.holding || !axis.setpoint_deg)) {
      axis.setpoint_deg = axis.mount_deg;
    }
    axis.holding = true;
    target_deg = setpoint ? *axis.setpoint_deg : axis.mount_deg;
    rate_deg_s = 0.0;
  } else {
    axis.holding = false;
  }
  switch (axis.drive.kind) {
    case DriveKind::Relay:
      return drive_relay(axis, now_s, *target_deg, rate_deg_s);
    case DriveKind::Setpoint:
      return drive_setpoint(axis, now_s, *target_deg);
    case DriveKind::Pwm:
      break;
  }
  return drive_pwm(axis, now_s, *target_deg, rate_deg_s);
}

double StationController::drive_pwm(Axis& axis, double now_s, double target_deg,
                                    double rate_deg_s) const {
  double duty = axis.controller.update(target_deg, axis.mount_deg, rate_deg_s, config_.tick_s);
  if (into_limit(axis, duty)) {
    // Held at the switch: the supervisor sees an axis at rest, not one driven without moving.
    axis.controller.halt();
    duty = 0.0;
  }
  const auto verdict = axis.supervisor.check(now_s, duty);
  if (!verdict.allow_motion) axis.controller.halt();
  return axis.controller.duty();
}

double StationController::drive_relay(Axis& axis, double now_s, double target_deg,
                                      double rate_deg_s) const {
  double duty = relay_duty(axis.relay.update(target_deg, axis.mount_deg, now_s, rate_deg_s));
  if (into_limit(axis, duty)) {
    axis.relay.halt(now_s);
    duty = 0.0;
  }
  const auto verdict = axis.supervisor.check(now_s, duty);
  if (!verdict.allow_motion) axis.relay.halt(now_s);
  return axis.duty();
}

double StationController::drive_setpoint(Axis& axis, double now_s, double target_deg) const {
  double setpoint = target_deg;
  const double away = setpoint - axis.mount_deg;
  // A setpoint beyond a tripped switch becomes "stay here": the box would drive into it.
  if (into_limit(axis, away)) setpoint = axis.mount_deg;
  const double error = setpoint - axis.mount_deg;
  axis.setpoint_duty =
      std::fabs(error) > axis.drive.setpoint_band_deg ? std::copysign(1.0, error) : 0.0;
  axis.setpoint_deg = setpoint;
  const auto verdict = axis.supervisor.check(now_s, axis.setpoint_duty);
  if (!verdict.allow_motion) {
    axis.setpoint_deg = axis.mount_deg;
    axis.setpoint_duty = 0.0;
  }
  return axis.setpoint_duty;
}

double StationController::drive_test(Axis& axis, double now_s, int direction) const {
  // Slow, so a wrong way is seen before it goes far: below the supervisor's "driven" duty where the
  // motor still turns past its stiction. A relay has one speed; a setpoint box is given a goal a
  // few degrees on, renewed each tick, so it keeps going the one way for the test's second.
  constexpr double kTestDuty = 0.35;
  constexpr double kSetpointLeadDeg = 5.0;
  axis.holding = false;
  double duty = 0.0;
  switch (axis.drive.kind) {
    case DriveKind::Pwm:
      duty = axis.controller.drive_open(
          direction * std::max(kTestDuty, axis.controller.config().min_duty + 0.1), config_.tick_s);
      break;
    case DriveKind::Relay:
      duty = relay_duty(
          axis.relay.update(axis.mount_deg + direction * kSetpointLeadDeg, axis.mount_deg, now_s));
      break;
    case DriveKind::Setpoint:
      axis.setpoint_deg = axis.mount_deg + direction * kSetpointLeadDeg;
      duty = axis.setpoint_duty = direction;
      break;
  }
  // The supervisor still stops it for a stale reading, a latched fault or the E-stop, but is not
  // asked to judge the motion: which way the shaft goes is the test's question, and a reversed
  // motor must come back as its answer rather than as a latched runaway.
  if (into_limit(axis, duty) || !axis.supervisor.check(now_s, 0.0).allow_motion) {
    axis.halt(now_s);
    return 0.0;
  }
  return duty;
}

bool StationController::into_limit(const Axis& axis, double duty) const {
  const bool azimuth = &axis == &az_;
  if (duty > 0.0) return azimuth ? limits_.az_cw : limits_.el_up;
  if (duty < 0.0) return azimuth ? limits_.az_ccw : limits_.el_down;
  return false;
}

Duties StationController::set_limits(const LimitSwitches& limits) {
  limits_ = limits;
  for (Axis* axis : {&az_, &el_}) {
    // No time here: a relay's dead times then run from its next update.
    if (into_limit(*axis, axis->duty())) axis->halt(std::numeric_limits<double>::quiet_NaN());
  }
  return duties();
}

std::optional<AzEl> StationController::sky_position(double now_s) const {
  if (faulted() || az_.supervisor.stale(now_s) || el_.supervisor.stale(now_s)) return std::nullopt;
  // Past the zenith on a flip mount the beam looks the other way: (az + 180, 180 − el).
  if (el_.mount_deg > 90.0) return AzEl{wrap_360(az_.mount_deg + 180.0), 180.0 - el_.mount_deg};
  return AzEl{wrap_360(az_.mount_deg), el_.mount_deg};
}

bool StationController::faulted() const {
  return az_.supervisor.fault() != FaultKind::None || el_.supervisor.fault() != FaultKind::None;
}

AxisStatus StationController::status(const Axis& axis) {
  return AxisStatus{axis.mount_deg, axis.duty(), axis.moving(), axis.supervisor.fault(),
                    axis.supervisor.reason()};
}

std::uint64_t StationController::starts(const Axis& axis) {
  switch (axis.drive.kind) {
    case DriveKind::Relay:
      return axis.relay.starts();
    case DriveKind::Pwm:
    case DriveKind::Setpoint:
      return axis.controller.starts();
  }
  return axis.controller.starts();
}

void StationController::emergency_stop(double now_s, std::string_view reason) {
  for (Axis* axis : {&az_, &el_}) {
    axis->supervisor.emergency_stop(now_s, reason);
    axis->halt(now_s);
  }
}

void StationController::clear_faults() {
  az_.supervisor.clear();
  el_.supervisor.clear();
}

}  // namespace azt::control
