#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::control {

// A brake on an axis (the Hy-Gain HAM-IV/T-2X wedge brake, a motor with a spring-applied
// electromagnetic brake): released by energising its solenoid, applied by a spring when the
// power goes, so a dead controller leaves the axis braked. It must be off before the motor
// pulls (K3NG #55: a T-2X's "start of rotation … is faster than the brake solenoid and the rotor
// obviously does not start"; the reporter asks for 0.5–1 s), and must not be applied while the
// axis still turns (it would grind the wedge or the pads).

enum class BrakeState : std::uint8_t {
  Engaged,    ///< output off, brake holding; the motor is held at zero
  Releasing,  ///< output on for less than release_s; the motor is held at zero
  Released,   ///< output on, brake off: the only state in which the motor may be driven
  Idle,       ///< released, motion stopped less than idle_s ago (a pause between moves)
  Engaging,   ///< output off for less than engage_s; the motor is held at zero
};

std::string_view to_string(BrakeState state);

struct BrakeConfig {
  /// From the release output going on to the brake being off: K3NG #55's reporter asks for
  /// 0.5–1 s on a T-2X. (0, 10] s.
  double release_s = 1.0;
  /// From the output going off to the brake holding: no new motion until then (a release
  /// command to a half-applied brake would start the motor against it). [0, 10] s.
  double engage_s = 0.5;
  /// The wanted duty has been zero this long before the brake is applied: the axis coasts to
  /// rest first, and a tracking pause between moves does not cycle the brake. [0, 600] s.
  double idle_s = 2.0;

  /// Validates every field; errors name it.
  static Result<BrakeConfig> make(const BrakeConfig& c);
};

/// The brake of one axis, between the axis's controller and its drive. Pure: time is a
/// parameter (seconds of a monotonic clock).
///
/// Whatever the controller wants, the duty that leaves update() is zero unless the brake has been
/// fully released (output on for at least release_s); a stop applies the brake only after the
/// wanted duty has been zero for idle_s, and a new move after an engage waits for the engage to
/// finish and then for a full release.
///
/// Plugged in by DrivenAxis (driven_axis.hpp), each tick: duty = brake.update(wanted, now_s)
/// with the duty the controller (or homing) wants after the supervisor's verdict; write
/// release_output() to the brake's line with the drive. While holding() the axis calls its
/// controller's halt() so the soft start begins from zero once released (the controller would
/// otherwise ramp up against the brake and jump). halt() on every safety stop: the brake is
/// applied at once (the safety of a spring brake is that it holds).
class Brake {
 public:
  /// Precondition: BrakeConfig::make(config).ok(). Starts Engaged.
  explicit Brake(const BrakeConfig& config) : config_(config) {}

  /// One tick: the duty the motor may have. A non-finite duty or time, or a time earlier than
  /// the last tick's, applies the brake at once (halt) and returns 0.
  double update(double wanted_duty, double now_s);
  /// Applies the brake at once (output off) and forces zero duty until engage_s has passed and
  /// the brake has been released again.
  void halt(double now_s);

  [[nodiscard]] BrakeState state() const { return state_; }
  /// Whether the brake's line is energised (the brake is or is being released).
  [[nodiscard]] bool release_output() const;
  /// The motor must not be driven: anything but Released (Idle too, until motion resumes).
  [[nodiscard]] bool holding() const { return state_ != BrakeState::Released; }
  /// Brake applications since construction (each wears it).
  [[nodiscard]] std::uint64_t engagements() const { return engagements_; }
  [[nodiscard]] const BrakeConfig& config() const { return config_; }

 private:
  void enter(BrakeState state, double now_s);
  void advance(bool wants_motion, double now_s);
  void engage(double now_s);

  BrakeConfig config_;
  BrakeState state_ = BrakeState::Engaged;
  double since_s_ = 0.0;  ///< when the present state began
  std::optional<double> last_now_s_;
  std::uint64_t engagements_ = 0;
};

}  // namespace azt::control
