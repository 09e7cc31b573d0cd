#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::control {

// A pulse-counted axis knows how far it moved, not where it is: at start (and after a lost
// count) it drives to a home switch (a limit switch at one end of travel, or an index switch)
// and counts from there. The sequence follows the common practice of rotator firmwares: seek the
// switch, and fail with a reason if it is not found within the travel (SatNOGS' stepper firmware
// seeks each axis towards its end-stop and reports a homing error when the seek completes
// without it, satnogs-rotator-firmware, stepper_motor_controller.ino), then stop, back off and
// come back slowly, so the home count is taken at the same speed every time.
//
// Every later close of the home switch is a free check of the count: it must read what it read at
// homing. A reed sensor loses pulses (motor noise, a pulse during a reversal, a slipping magnet)
// and the error only grows; a difference beyond the tolerance latches "position lost".

enum class HomingState : std::uint8_t {
  NotHomed,       ///< no reference yet: tracking refused
  Seeking,        ///< driving towards the home switch at seek_duty
  Stopping,       ///< duty 0 for stop_s, the motor coasting to rest, before the next move
  BackingOff,     ///< driving away at slow_duty until the switch has been open for backoff_s
  Reapproaching,  ///< driving back towards the switch at slow_duty
  Homed,          ///< the count is referenced: counts_from_home() answers
  Failed,         ///< homing gave up (timeout, travel, no pulses, stuck switch): reason()
  PositionLost,   ///< a pass of the home switch disagreed with the home count: reason()
};

std::string_view to_string(HomingState state);

struct HomingConfig {
  /// Signed duty of the seek: its sign is the direction of the home switch (negative: the switch
  /// is at the low end, e.g. an actuator's retracted end), |seek_duty| in (0, 1].
  double seek_duty = -0.6;
  /// |duty| of the back-off and the re-approach, (0, 1]: slow, so the switch is met at the same
  /// speed every time.
  double slow_duty = 0.25;
  /// Come back to the switch slowly after backing off and take the home count there; false:
  /// the home count is the one at the seek's (faster) switch edge.
  bool reapproach = true;
  double stop_s = 1.0;     ///< at rest this long between moves (the motor coasts; dead time)
  double backoff_s = 1.0;  ///< keep backing off this long after the switch opened
  /// Each phase (seek, back-off, re-approach) gives up after this long.
  double phase_timeout_s = 120.0;
  /// … or after this many counts without reaching its goal: more than the whole travel means
  /// the switch was passed or is broken. Must be > 0.
  std::int64_t max_travel_counts = 10000;
  /// Driven this long without a single counted pulse: the motor, the sensor or its wiring (an
  /// actuator's own end switch cuts the motor when the home switch is missed).
  double no_pulse_s = 3.0;
  /// A pass of the home switch may read this many counts off the home count before the position
  /// counts as lost. An index switch passable both ways makes at different places in the two
  /// directions (its hysteresis): the tolerance must cover that.
  std::int64_t tolerance_counts = 1;

  /// Validates every field; errors name it.
  static Result<HomingConfig> make(const HomingConfig& c);
};

/// The homing state machine of one pulse-counted axis. Pure: time is a parameter, in seconds of
/// the monotonic clock the edges are stamped with.
///
/// Plugged in by PulseAxis (pulse_axis.hpp), which DrivenAxis runs:
///  - start() at start-up (when configured) or on the operator's command; reset() on the
///    operator's clear of a latched fault (back to NotHomed: home again).
///  - every tick: the home switch's edges, in timestamp order with the pulse edges (see
///    PulseCounter), to on_switch() with the counter's count at that moment; then, while
///    active(), the axis obeys update()'s duty instead of the tracking controller (still
///    through the supervisor, the brake and the trips, which may stop it: then abort()).
///  - targets are refused while why_not_homed() has words; once homed, the position is
///    PulseScale::angle_deg(counts_from_home(count)).
///  - state() PositionLost is a latched fault: stop the axis and show reason().
class Homing {
 public:
  /// Precondition: HomingConfig::make(config).ok().
  explicit Homing(const HomingConfig& config) : config_(config) {}

  /// Begins (or restarts) homing at `now_s` from count `count`; `switch_closed` is the home
  /// switch's level now (already on it: back off first).
  void start(double now_s, std::int64_t count, bool switch_closed);
  /// The home switch changed at `at_s`; `count` is the counter's count at that moment.
  void on_switch(bool closed, double at_s, std::int64_t count);
  /// One tick: the duty homing wants now (0 unless active()). Checks the timeouts and the
  /// travel. A non-finite or backwards `now_s` fails homing.
  double update(double now_s, std::int64_t count);
  /// Stops homing (the operator's STOP, a fault elsewhere): back to NotHomed with the reason.
  void abort(std::string_view reason);
  /// The operator's reset: back to NotHomed, whatever the state.
  void reset();

  [[nodiscard]] HomingState state() const { return state_; }
  [[nodiscard]] bool active() const;
  [[nodiscard]] bool homed() const { return state_ == HomingState::Homed; }
  /// Why tracking must wait, in the operator's words ("not homed: …"); empty once homed.
  [[nodiscard]] std::optional<std::string> why_not_homed() const;
  /// The failure or the loss, without the "not homed" prefix.
  [[nodiscard]] const std::string& reason() const { return reason_; }
  /// Counts from the home switch's make point; empty unless homed.
  [[nodiscard]] std::optional<std::int64_t> counts_from_home(std::int64_t count) const;
  /// The last pass's count minus the home count (0 at homing); empty before homing.
  [[nodiscard]] std::optional<std::int64_t> last_pass_difference() const { return last_pass_; }
  [[nodiscard]] const HomingConfig& config() const { return config_; }

 private:
  void enter(HomingState state, double now_s, std::int64_t count);
  void fail_with(std::string reason);
  void check_pass(std::int64_t count);
  void on_switch_closed(double at_s, std::int64_t count);
  [[nodiscard]] double phase_duty() const;
  void check_phase(double now_s, std::int64_t count);
  [[nodiscard]] std::int64_t progress_counts(std::int64_t count) const;
  [[nodiscard]] std::optional<std::string> phase_failure(double now_s, std::int64_t count) const;
  void finish_stop(double now_s, std::int64_t count);
  [[nodiscard]] std::string_view phase_name() const;

  HomingConfig config_;
  HomingState state_ = HomingState::NotHomed;
  HomingState after_stop_ = HomingState::BackingOff;  ///< where Stopping goes next
  std::string reason_;
  double phase_start_s_ = 0.0;
  std::int64_t phase_start_count_ = 0;
  double last_pulse_s_ = 0.0;  ///< when the count last changed during the phase
  std::int64_t last_count_ = 0;
  bool switch_closed_ = false;
  std::optional<double> switch_open_since_s_;  ///< backing off: the switch open since then
  std::optional<double> last_now_s_;
  std::optional<std::int64_t> seek_edge_count_;  ///< the count at the seek's switch edge
  std::int64_t home_count_ = 0;
  std::optional<std::int64_t> last_pass_;
};

}  // namespace azt::control
