#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::control {

/// What stops an axis. Stale readings stop the motors for as long as they last; every other
/// kind latches until clear(). MotorTrip is never the supervisor's own: DrivenAxis reports its
/// motor protection's trip (motor_trips.hpp) with it, and PositionLost a pulse-counted axis's
/// missed pulses found at the home switch (pulse_axis.hpp).
enum class FaultKind {
  None,
  StalePosition,
  Stall,
  Runaway,
  EncoderJump,
  EStop,
  MotorTrip,
  PositionLost
};

std::string_view to_string(FaultKind kind);

struct SupervisorConfig {
  double stale_s = 0.2;             ///< no valid reading for this long stops the motors
  double stall_window_s = 2.0;      ///< driven this long …
  double stall_min_move_deg = 0.5;  ///< … and moved less than this: stalled
  double driven_duty = 0.5;         ///< |duty| from which the axis counts as driven
  double runaway_deg = 0.5;         ///< driven towards the goal yet the distance grew this much
  double max_rate_deg_s = 1.5;      ///< fastest plausible axis speed
  /// Tolerance above max_rate·Δt (backlash, quantization); never less than two encoder steps,
  /// or every count of a coarse encoder would look like a jump.
  double jump_margin_deg = 0.2;
  double lsb_deg = 0.0;         ///< one encoder step (360/2^bits); 0 if unknown
  double jump_persist_s = 0.5;  ///< implausible readings for this long become a fault

  static Result<SupervisorConfig> make(const SupervisorConfig& c);
};

/// The verdict for one tick.
struct SupervisorVerdict {
  bool allow_motion = false;           ///< false: drive the motor to zero now
  std::optional<double> position_deg;  ///< the accepted reading, if any
};

/// The safety state machine of one axis (pure: time is a parameter, in seconds of a monotonic
/// clock). Per tick, in this order: offer the new reading (if one arrived) with on_reading(),
/// then call check() with the duty the controller wants. A fault detected in check() forbids
/// motion in the same tick.
class AxisSupervisor {
 public:
  explicit AxisSupervisor(const SupervisorConfig& config) : config_(config) {}

  /// A new position reading at `now_s`. Returns false if it was rejected as an implausible jump
  /// (the last good position stays in use).
  bool on_reading(double now_s, double position_deg);

  /// Runaway is judged on the shaft's own motion against the driven direction, never on the
  /// distance to the goal: a goal that jumps further away (a new target from a PC program) must
  /// not look like a reversed motor.
  SupervisorVerdict check(double now_s, double duty);

  /// The reading's calibration changed by `delta_deg` (a new offset or correction): shift what was
  /// remembered of past readings so the change is not taken for a jump or for motion.
  void rebase(double delta_deg);

  /// The E-stop input went active (or the station stops for another reason, given in words):
  /// latches.
  void emergency_stop(double now_s, std::string_view reason = "emergency stop input active");

  /// Clears a latched fault (an operator's decision); the motion history restarts. A cause that
  /// persists (E-stop input still active, shaft still stuck) latches again on its next detection.
  void clear();

  [[nodiscard]] FaultKind fault() const { return fault_; }
  [[nodiscard]] const std::string& reason() const { return reason_; }
  [[nodiscard]] bool stale(double now_s) const;

 private:
  void latch(FaultKind kind, std::string reason);
  void watch_motion(double now_s, double duty);

  SupervisorConfig config_;
  FaultKind fault_ = FaultKind::None;
  std::string reason_;
  std::optional<double> last_good_deg_;
  double last_good_s_ = 0.0;
  std::optional<double> first_rejected_s_;
  // Motion watch: start of the present driven stretch, the position then, and the furthest the
  // axis has moved in the driven direction since (degrees, positive = the commanded way).
  std::optional<double> driven_since_s_;
  double driven_start_deg_ = 0.0;
  double driven_best_progress_deg_ = 0.0;
  double driven_direction_ = 0.0;
};

}  // namespace azt::control
