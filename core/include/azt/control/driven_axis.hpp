#pragma once
// One driven axis of a station: its controller, its supervisor, how its motor is moved (PWM,
// relays or a setpoint box) and its pair of travel-end switches. StationController holds two of
// them (azimuth and elevation) and PortedStation a third for the polarisation feed
// (pol_target.hpp); a station of one axis, a brake or a motor trip is added here once rather than
// per axis.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "azt/control/axis_controller.hpp"
#include "azt/control/brake.hpp"
#include "azt/control/motor_trips.hpp"
#include "azt/control/pulse_axis.hpp"
#include "azt/control/relay_drive.hpp"
#include "azt/control/supervisor.hpp"

namespace azt::control {

/// How an axis is moved (docs/hardware.md): a PWM H-bridge (soft start and stop, AxisController),
/// on/off relays (RelayDrive: hysteresis, minimum on-time, reversal dead time), or a rotator box
/// that closes its own loop around a setpoint (seed 001's digital pot: we only send the angle).
enum class DriveKind : std::uint8_t { Pwm, Relay, Setpoint };

std::string_view to_string(DriveKind kind);
/// Whether the drive is sent an angle (the box closes the loop) rather than a duty.
bool sends_setpoint(DriveKind kind);

struct AxisDriveConfig {
  DriveKind kind = DriveKind::Pwm;
  RelayDriveConfig relay;  ///< Relay: window, minimum on-time, dead times
  /// Setpoint: the box's own deadband. Further than this from the setpoint the box is driving,
  /// which is what the supervisor watches for stalls and runaways.
  double setpoint_band_deg = 2.0;
  /// A brake to release before the motor may pull (brake.hpp); empty: no brake, the motor is
  /// driven at once.
  std::optional<BrakeConfig> brake;
  /// The motor's protection (motor_trips.hpp): current, temperature, the driver's fault line;
  /// empty: nothing watched at the motor.
  std::optional<MotorTripsConfig> trips;
  /// A pulse-counted position (pulse_axis.hpp): the axis homes before it tracks, and its
  /// readings come from on_pulse_edges(). Precondition: PulseAxis::make(*pulses).ok(), and a
  /// duty-driven axis (a setpoint box closes its own loop on its own sensor).
  std::optional<PulseAxisConfig> pulses;
  /// The sensor's own coarsest step, where it is not the mount's encoder resolution: a pot on a
  /// linear actuator, whose degrees per count vary along the stroke
  /// (PotInputConfig::max_deg_per_count). A pulse-counted axis takes its scale's instead.
  std::optional<double> sensor_step_deg;
};

/// What the station knows of one axis.
struct AxisStatus {
  double mount_deg = 0.0;  ///< last accepted reading, mount degrees
  double duty = 0.0;
  bool moving = false;
  FaultKind fault = FaultKind::None;
  std::string reason;               ///< the supervisor's (or the motor trip's) words when faulted
  std::optional<BrakeState> brake;  ///< empty: the axis has no brake
  bool brake_release =
      false;  ///< the brake's line is energised (the brake is or is being released)
  /// Why the operator's last clear left a motor trip latched (its cause is still there); empty
  /// otherwise.
  std::string reset_refused;
  /// A pulse-counted axis: its homing's state; empty for any other sensor.
  std::optional<HomingState> homing;
  /// Why the axis holds rather than tracks its target: a pulse-counted axis not (yet) homed, in
  /// Homing's words ("not homed: homing in progress (…)"); empty otherwise.
  std::string held;
  /// A pulse-counted axis: the counter's count (from where it started, not from home).
  std::optional<std::int64_t> pulse_count;
  /// The motor's last current and temperature readings, when the axis has such inputs.
  std::optional<double> current_a;
  std::optional<double> temperature_c;
};

/// One axis's travel-end switches (docs/hardware.md), tripped or not: `reverse` at the end of
/// decreasing angle (counter-clockwise, down), `forward` at the end of increasing angle.
struct LimitPair {
  bool reverse = false;
  bool forward = false;
};

class DrivenAxis {
 public:
  /// `start_mount_deg`: where the axis is believed to be before its first reading. The
  /// supervisor is given the controller's encoder step.
  DrivenAxis(const AxisControlConfig& control, const SupervisorConfig& supervisor,
             const AxisDriveConfig& drive, double start_mount_deg, double tick_s);

  /// A reading in mount degrees: kept unless the supervisor rejects it as a jump.
  void on_reading(double now_s, double mount_deg);
  /// The reading's calibration moved by `delta_deg` (new corrections): not a jump, not motion.
  void rebase(double delta_deg);

  /// One tick towards `target_deg` (nullopt: hold where it stands), `rate_deg_s` the target's
  /// own rate as feed-forward. Returns the duty (relays ±1/0, a setpoint box its direction).
  double drive(double now_s, std::optional<double> target_deg, double rate_deg_s);
  /// The direction test's open-loop drive (Demand::test): slowly, one way.
  double drive_test(double now_s, int direction);
  /// Stops the drive now, whatever its kind (a setpoint axis is sent where it stands), and
  /// applies the brake at once: every caller is a safety stop.
  void halt(double now_s);
  /// This tick's motor readings (current, temperature, the driver's fault line), when the axis
  /// has motor protection: a trip stops the axis at once and latches as a MotorTrip fault.
  void on_motor_readings(double now_s, const MotorReadings& readings);
  /// The switches changed (an input edge): a drive into a tripped one stops at once.
  void set_limits(const LimitPair& limits);

  /// Pulse-counted axes, each tick before drive(): the edges since the last tick, oldest first
  /// (ports::PulseInput). The count and the home switch give this tick's reading.
  void on_pulse_edges(double now_s, std::span<const ports::PulseEdge> edges);
  /// Starts homing (at start-up when configured, or on the operator's command); `home_closed`
  /// is the switch's level now. Returns why not (no pulse sensor, a fault that must be cleared
  /// first); a lost position is no reason: homing is its cure.
  std::optional<std::string> home(double now_s, bool home_closed);
  /// Ends a homing in progress (the operator's STOP from any source): the axis stops and stays
  /// unreferenced with `reason` until homed again. Nothing to do when homing is not active.
  void stop_homing(double now_s, std::string_view reason);
  /// The pulse sensor, for its counts and words; null for any other sensor.
  [[nodiscard]] const PulseAxis* pulses() const { return pulses_ ? &*pulses_ : nullptr; }

  void emergency_stop(double now_s, std::string_view reason);
  /// The operator's reset: the supervisor's faults, and a motor trip unless its cause remains
  /// (then the trip stays and status().reset_refused says why).
  void clear_faults();

  [[nodiscard]] double mount_deg() const { return mount_deg_; }
  [[nodiscard]] double duty() const;
  [[nodiscard]] bool moving() const;
  /// Motor starts since construction (a relay closing, or a PWM move beginning).
  [[nodiscard]] std::uint64_t starts() const;
  [[nodiscard]] AxisStatus status() const;
  /// Setpoint axes: the angle to send; nullopt for duty-driven axes.
  [[nodiscard]] std::optional<double> setpoint_deg() const;
  [[nodiscard]] bool faulted() const {
    return supervisor_.fault() != FaultKind::None || tripped() || pulse_faulted();
  }
  [[nodiscard]] bool tripped() const { return trips_ && trips_->tripped() != MotorTrip::None; }
  /// A pulse-counted axis lost its position (a pass of the home switch disagreed) or counted
  /// outside its stroke: latched until the operator clears it or homes again.
  [[nodiscard]] bool pulse_faulted() const {
    return !pulse_fault_.empty() || (pulses_ && pulses_->position_lost());
  }
  [[nodiscard]] bool stale(double now_s) const { return supervisor_.stale(now_s); }
  [[nodiscard]] const AxisControlConfig& control_config() const { return controller_.config(); }

 private:
  double drive_pwm(double now_s, double target_deg, double rate_deg_s);
  double drive_relay(double now_s, double target_deg, double rate_deg_s);
  double drive_setpoint(double now_s, double target_deg);
  /// A duty that runs into a tripped switch.
  [[nodiscard]] bool into_limit(double duty) const;
  /// Whether the drive may keep the duty it wants this tick: not while faulted, tripped, stale or
  /// braked. Applies the brake at once on a safety stop, and tells the supervisor the duty the
  /// motor really gets (zero while the brake holds: no stall is counted against a brake).
  [[nodiscard]] bool gate(double now_s, double wanted_duty);
  /// Stops the controller, the relays or the setpoint box, leaving the brake as it is.
  void halt_drive(double now_s);
  [[nodiscard]] std::uint64_t drive_starts() const;
  /// Starts the drive counted in a tick whose duty never reached the motor are not starts.
  void uncount_starts(std::uint64_t before, double duty);
  /// Homing's tick while it is active: its duty, open loop like the direction test (the
  /// supervisor stops it for a stale count, a fault or the E-stop; homing itself judges the
  /// motion: no pulses, the wrong way, too far); nullopt once homing is not active.
  std::optional<double> drive_homing(double now_s);
  /// The pulse count's position as this tick's reading; the reference moving at homing is a
  /// rebase, not a jump.
  void pulse_reading(double now_s);
  /// Tells the pulse counter the duty the motor gets (its direction for a single channel).
  void note_pulse_drive(double duty, double now_s);

  AxisController controller_;
  AxisSupervisor supervisor_;
  AxisDriveConfig drive_;
  RelayDrive relay_;
  double mount_deg_;
  double tick_s_;
  LimitPair limits_;
  std::optional<double> setpoint_deg_;  ///< Setpoint axes: what the box was last given
  double setpoint_duty_ = 0.0;          ///< Setpoint axes: the direction the box drives
  bool holding_ = false;                ///< the last tick had no target (STOP, or holding)
  std::optional<Brake> brake_;
  std::optional<MotorTrips> trips_;
  std::string reset_refused_;
  std::uint64_t unstarted_ = 0;  ///< drive starts withheld by the brake or a stop in their tick
  std::optional<PulseAxis> pulses_;
  /// Not homed: the position of count zero (where the axis was believed to be at start, carried
  /// on when a position is lost).
  double pulse_origin_deg_ = 0.0;
  bool pulses_homed_ = false;  ///< homed as of the last reading (a change moves the reference)
  std::string pulse_fault_;    ///< a count outside the stroke: latched
};

}  // namespace azt::control
