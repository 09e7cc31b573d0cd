// DrivenAxis's pulse-counted sensor (pulse_axis.hpp): its readings, its homing moves and the
// operator's command to home. Apart from driven_axis.cpp so the axis's other parts stay readable.
#include <cmath>
#include <string>

#include "azt/control/driven_axis.hpp"
#include "relay_duty.hpp"

namespace azt::control {
namespace {

/// How far ahead of the axis a relay drive is aimed while homing: beyond its window, so it keeps
/// driving one way until homing's duty changes.
constexpr double kRelayLeadDeg = 5.0;

}  // namespace

void DrivenAxis::note_pulse_drive(double duty, double now_s) {
  // set_limits() halts without a time: the next tick's duty sets the direction then.
  if (pulses_ && std::isfinite(now_s)) pulses_->set_drive(duty, now_s);
}

void DrivenAxis::on_pulse_edges(double now_s, std::span<const ports::PulseEdge> edges) {
  if (!pulses_) return;
  pulses_->on_edges(edges);
  pulse_reading(now_s);
}

void DrivenAxis::pulse_reading(double now_s) {
  const bool homed = pulses_->homed();
  if (!homed && pulses_homed_) {
    // The reference is gone (a lost position): carry on unreferenced from where the axis was
    // believed to be, so the supervisor sees no jump.
    pulse_origin_deg_ = mount_deg_ - static_cast<double>(pulses_->counter().count()) *
                                         pulses_->nominal_deg_per_count();
  }
  auto position = pulses_->position_deg(pulse_origin_deg_);
  if (!position) {
    if (pulse_fault_.empty()) {
      pulse_fault_ = position.error().message;
      halt(now_s);
    }
    return;
  }
  if (homed && !pulses_homed_) rebase(*position - mount_deg_);  // referenced now: not a jump
  pulses_homed_ = homed;
  on_reading(now_s, *position);
}

std::optional<std::string> DrivenAxis::home(double now_s, bool home_closed) {
  if (!pulses_) return std::string{"this axis has no pulse sensor to home"};
  if (sends_setpoint(drive_.kind)) {
    return std::string{"a setpoint drive closes its own loop: it cannot be homed"};
  }
  if (supervisor_.fault() != FaultKind::None || tripped()) {
    return "the axis is stopped (" + status().reason + "): clear the fault first";
  }
  pulse_fault_.clear();
  pulses_->start_homing(now_s, home_closed);
  return std::nullopt;
}

void DrivenAxis::stop_homing(double now_s, std::string_view reason) {
  if (!pulses_ || !pulses_->homing_active()) return;
  pulses_->abort(reason);
  halt(now_s);
}

std::optional<double> DrivenAxis::drive_homing(double now_s) {
  const auto wanted = pulses_->homing_duty(now_s);
  pulse_reading(now_s);  // a homing that ended this tick references the count now
  if (!wanted) return std::nullopt;
  holding_ = false;
  const std::uint64_t before = drive_starts();
  double duty = 0.0;
  switch (drive_.kind) {
    case DriveKind::Pwm:
      duty = controller_.drive_open(*wanted, tick_s_);
      break;
    case DriveKind::Relay: {
      // One speed: the slow back-off and re-approach run at the relay's speed too.
      const double goal_deg =
          *wanted == 0.0 ? mount_deg_ : mount_deg_ + std::copysign(kRelayLeadDeg, *wanted);
      duty = relay_duty(relay_.update(goal_deg, mount_deg_, now_s));
      break;
    }
    case DriveKind::Setpoint:
      pulses_->abort("a setpoint drive closes its own loop: it cannot be homed");
      return 0.0;
  }
  if (faulted() || !supervisor_.check(now_s, 0.0).allow_motion) {
    halt(now_s);
    uncount_starts(before, 0.0);
    const std::string why = status().reason;
    pulses_->abort(why.empty() ? "the position reading went stale" : why);
    return 0.0;
  }
  // Into a tripped switch, or the brake still being released: nothing this tick. Homing's own
  // no-pulse check gives up with words if it stays so.
  if (into_limit(duty) || (brake_ && brake_->update(duty, now_s) != duty)) {
    halt_drive(now_s);
    uncount_starts(before, 0.0);
    return 0.0;
  }
  note_pulse_drive(duty, now_s);
  return duty;
}

}  // namespace azt::control
