#include "azt/control/driven_axis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "relay_duty.hpp"

namespace azt::control {
namespace {

SupervisorConfig with_lsb(SupervisorConfig s, const AxisControlConfig& c) {
  s.lsb_deg = c.lsb_deg;
  return s;
}

/// A pulse-counted axis's step is one count at the coarse end of its scale (pulse_scale.hpp), an
/// actuator pot's one ADC count at the coarse end of its stroke, whatever the mount's encoder
/// resolution says: the controller's window and the supervisor's checks are in the steps the
/// sensor really has.
AxisControlConfig with_count_lsb(AxisControlConfig c, const AxisDriveConfig& drive) {
  if (drive.pulses) {
    c.lsb_deg = PulseAxis::make(*drive.pulses).value().scale().max_deg_per_count();
  } else if (drive.sensor_step_deg) {
    c.lsb_deg = *drive.sensor_step_deg;
  }
  return c;
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

DrivenAxis::DrivenAxis(const AxisControlConfig& control, const SupervisorConfig& supervisor,
                       const AxisDriveConfig& drive, double start_mount_deg, double tick_s)
    : controller_(with_count_lsb(control, drive)),
      supervisor_(with_lsb(supervisor, controller_.config())),  // the step just chosen
      drive_(drive),
      relay_(drive.relay),
      mount_deg_(start_mount_deg),
      tick_s_(tick_s) {
  if (drive.brake) brake_.emplace(*drive.brake);
  if (drive.trips) trips_.emplace(*drive.trips);
  if (drive.pulses) {
    pulses_.emplace(PulseAxis::make(*drive.pulses).value());
    pulse_origin_deg_ = start_mount_deg;
  }
}

void DrivenAxis::on_reading(double now_s, double mount_deg) {
  if (supervisor_.on_reading(now_s, mount_deg)) mount_deg_ = mount_deg;
}

void DrivenAxis::rebase(double delta_deg) {
  mount_deg_ += delta_deg;
  supervisor_.rebase(delta_deg);
}

double DrivenAxis::duty() const {
  switch (drive_.kind) {
    case DriveKind::Relay:
      return relay_duty(relay_.command());
    case DriveKind::Setpoint:
      return setpoint_duty_;
    case DriveKind::Pwm:
      break;
  }
  return controller_.duty();
}

bool DrivenAxis::moving() const {
  switch (drive_.kind) {
    case DriveKind::Pwm:
      return controller_.moving();  // through its soft stop, while the duty winds down
    case DriveKind::Relay:
    case DriveKind::Setpoint:
      return duty() != 0.0;
  }
  return duty() != 0.0;
}

std::uint64_t DrivenAxis::starts() const { return drive_starts() - unstarted_; }

std::uint64_t DrivenAxis::drive_starts() const {
  switch (drive_.kind) {
    case DriveKind::Relay:
      return relay_.starts();
    case DriveKind::Pwm:
    case DriveKind::Setpoint:
      return controller_.starts();
  }
  return controller_.starts();
}

AxisStatus DrivenAxis::status() const {
  AxisStatus s;
  s.mount_deg = mount_deg_;
  s.duty = duty();
  s.moving = moving();
  s.fault = supervisor_.fault();
  s.reason = supervisor_.reason();
  if (s.fault == FaultKind::None && tripped()) {
    s.fault = FaultKind::MotorTrip;
    s.reason = trips_->reason();
  }
  if (brake_) {
    s.brake = brake_->state();
    s.brake_release = brake_->release_output();
  }
  s.reset_refused = reset_refused_;
  if (pulses_) {
    if (s.fault == FaultKind::None && pulse_faulted()) {
      s.fault = FaultKind::PositionLost;
      s.reason = pulse_fault_.empty() ? pulses_->homing().reason() : pulse_fault_;
    }
    s.homing = pulses_->homing().state();
    s.held = pulses_->why_not_homed().value_or("");
    s.pulse_count = pulses_->counter().count();
  }
  if (trips_) {
    s.current_a = trips_->last_current_a();
    s.temperature_c = trips_->last_temperature_c();
  }
  return s;
}

std::optional<double> DrivenAxis::setpoint_deg() const {
  if (sends_setpoint(drive_.kind)) return setpoint_deg_;
  return std::nullopt;
}

void DrivenAxis::halt(double now_s) {
  halt_drive(now_s);
  if (brake_) brake_->halt(now_s);
}

void DrivenAxis::halt_drive(double now_s) {
  note_pulse_drive(0.0, now_s);
  controller_.halt();
  relay_.halt(now_s);
  if (sends_setpoint(drive_.kind)) {
    setpoint_deg_ = mount_deg_;
    setpoint_duty_ = 0.0;
  }
}

void DrivenAxis::set_limits(const LimitPair& limits) {
  limits_ = limits;
  // No time here: a relay's dead times then run from its next update.
  if (into_limit(duty())) halt(std::numeric_limits<double>::quiet_NaN());
}

void DrivenAxis::on_motor_readings(double now_s, const MotorReadings& readings) {
  if (!trips_) return;
  const bool was_tripped = tripped();
  if (!trips_->update(readings, now_s) && !was_tripped) halt(now_s);
}

void DrivenAxis::clear_faults() {
  supervisor_.clear();
  reset_refused_.clear();
  if (trips_) {
    if (auto why = trips_->reset()) reset_refused_ = std::move(*why);
  }
  // A lost or failed reference is not trusted again: the axis must home before it tracks.
  if (pulses_ && (pulse_faulted() || pulses_->homing().state() == HomingState::Failed)) {
    pulses_->reset();
  }
  pulse_fault_.clear();
}

void DrivenAxis::uncount_starts(std::uint64_t before, double duty) {
  if (duty == 0.0) unstarted_ += drive_starts() - before;
}

bool DrivenAxis::gate(double now_s, double wanted_duty) {
  // Faulted, tripped or stale: the brake is applied now and not released again until the axis
  // may move (it would otherwise be released and applied every engage_s while faulted).
  const bool blocked = faulted() || supervisor_.stale(now_s);
  double duty = blocked ? 0.0 : wanted_duty;
  if (brake_) {
    if (blocked) brake_->halt(now_s);
    duty = brake_->update(duty, now_s);
  }
  const auto verdict = supervisor_.check(now_s, duty);
  if (!verdict.allow_motion) {
    if (brake_) brake_->halt(now_s);
    return false;
  }
  return !blocked && duty == wanted_duty;
}

void DrivenAxis::emergency_stop(double now_s, std::string_view reason) {
  supervisor_.emergency_stop(now_s, reason);
  halt(now_s);
}

double DrivenAxis::drive(double now_s, std::optional<double> target_deg, double rate_deg_s) {
  if (pulses_) {
    if (auto duty = drive_homing(now_s)) return *duty;
    if (!pulses_->homed()) target_deg.reset();  // no angle to drive to until homed: hold
  }
  if (!target_deg) {
    // Holding: a PWM move finishes its soft stop at the present position. A setpoint axis is
    // sent where it stands when the hold begins (a STOP mid-move stops the box there), then
    // keeps that setpoint: re-sending the moving reading every tick would chase the coast.
    const bool setpoint = sends_setpoint(drive_.kind);
    if (setpoint && (!holding_ || !setpoint_deg_)) setpoint_deg_ = mount_deg_;
    holding_ = true;
    target_deg = setpoint ? *setpoint_deg_ : mount_deg_;
    rate_deg_s = 0.0;
  } else {
    holding_ = false;
  }
  const std::uint64_t before = drive_starts();
  double duty = 0.0;
  switch (drive_.kind) {
    case DriveKind::Relay:
      duty = drive_relay(now_s, *target_deg, rate_deg_s);
      break;
    case DriveKind::Setpoint:
      duty = drive_setpoint(now_s, *target_deg);
      break;
    case DriveKind::Pwm:
      duty = drive_pwm(now_s, *target_deg, rate_deg_s);
      break;
  }
  uncount_starts(before, duty);
  note_pulse_drive(duty, now_s);
  return duty;
}

double DrivenAxis::drive_pwm(double now_s, double target_deg, double rate_deg_s) {
  double duty = controller_.update(target_deg, mount_deg_, rate_deg_s, tick_s_);
  if (into_limit(duty)) {
    // Held at the switch: the supervisor sees an axis at rest, not one driven without moving.
    controller_.halt();
    duty = 0.0;
  }
  // While the brake holds the controller is halted, so its soft start begins from zero once the
  // brake is off rather than from whatever it ramped up to against the brake.
  if (!gate(now_s, duty)) controller_.halt();
  return controller_.duty();
}

double DrivenAxis::drive_relay(double now_s, double target_deg, double rate_deg_s) {
  double duty = relay_duty(relay_.update(target_deg, mount_deg_, now_s, rate_deg_s));
  if (into_limit(duty)) {
    relay_.halt(now_s);
    duty = 0.0;
  }
  if (!gate(now_s, duty)) relay_.halt(now_s);
  return this->duty();
}

double DrivenAxis::drive_setpoint(double now_s, double target_deg) {
  double setpoint = target_deg;
  // A setpoint beyond a tripped switch becomes "stay here": the box would drive into it.
  if (into_limit(setpoint - mount_deg_)) setpoint = mount_deg_;
  const double error = setpoint - mount_deg_;
  setpoint_duty_ = std::fabs(error) > drive_.setpoint_band_deg ? std::copysign(1.0, error) : 0.0;
  setpoint_deg_ = setpoint;
  if (!gate(now_s, setpoint_duty_)) {
    setpoint_deg_ = mount_deg_;
    setpoint_duty_ = 0.0;
  }
  return setpoint_duty_;
}

double DrivenAxis::drive_test(double now_s, int direction) {
  // Slow, so a wrong way is seen before it goes far: below the supervisor's "driven" duty where the
  // motor still turns past its stiction. A relay has one speed; a setpoint box is given a goal a
  // few degrees on, renewed each tick, so it keeps going the one way for the test's second.
  constexpr double kTestDuty = 0.35;
  constexpr double kSetpointLeadDeg = 5.0;
  holding_ = false;
  const std::uint64_t before = drive_starts();
  double duty = 0.0;
  switch (drive_.kind) {
    case DriveKind::Pwm:
      duty = controller_.drive_open(
          direction * std::max(kTestDuty, controller_.config().min_duty + 0.1), tick_s_);
      break;
    case DriveKind::Relay:
      duty =
          relay_duty(relay_.update(mount_deg_ + direction * kSetpointLeadDeg, mount_deg_, now_s));
      break;
    case DriveKind::Setpoint:
      setpoint_deg_ = mount_deg_ + direction * kSetpointLeadDeg;
      duty = setpoint_duty_ = direction;
      break;
  }
  // The supervisor still stops it for a stale reading, a latched fault or the E-stop, but is not
  // asked to judge the motion: which way the shaft goes is the test's question, and a reversed
  // motor must come back as its answer rather than as a latched runaway.
  if (into_limit(duty) || tripped() || !supervisor_.check(now_s, 0.0).allow_motion) {
    halt(now_s);
    uncount_starts(before, 0.0);
    return 0.0;
  }
  if (brake_ && brake_->update(duty, now_s) != duty) {
    halt_drive(now_s);  // the brake is being released: the test starts once it is off
    uncount_starts(before, 0.0);
    return 0.0;
  }
  note_pulse_drive(duty, now_s);
  return duty;
}

bool DrivenAxis::into_limit(double duty) const {
  if (duty > 0.0) return limits_.forward;
  if (duty < 0.0) return limits_.reverse;
  return false;
}

}  // namespace azt::control
