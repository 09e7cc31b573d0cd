#pragma once

#include <cstdint>

#include "azt/util/result.hpp"

namespace azt::control {

/// How one axis is driven. Angles are mount degrees; duty is signed, −1..+1, positive towards
/// increasing angle (clockwise azimuth seen from above, rising elevation).
struct AxisControlConfig {
  double window_deg = 0.0;        ///< the seed's movement window, 0.0–2.0°
  double lsb_deg = 360.0 / 4096;  ///< one encoder step (360/2^bits)
  double fast_zone_deg = 3.0;     ///< L1: beyond this error the axis runs at full speed
  double tracking_speed = 0.5;    ///< fraction of full speed inside L1 (the seed's "half speed")
  double max_rate_deg_s = 1.5;    ///< axis rate at full duty
  double ramp_s = 1.0;            ///< soft start/stop: time for the duty to go from 0 to 1
  double min_duty = 0.0;          ///< duty below which the motor does not turn (stiction)
  double time_constant_s = 0.3;   ///< motor speed response, sets the approach gain
  double backlash_deg = 0.0;      ///< gear play, driven through quickly when a move reverses
  bool lead = true;               ///< lead a moving target across the whole window

  /// Validates every field; errors name it.
  static Result<AxisControlConfig> make(const AxisControlConfig& c);
  /// L2 = window + 1 LSB: the antenna does not start while |error| ≤ L2 (seed, "Antenna Movement
  /// Window"); a window of 0 keeps a 1-LSB hysteresis.
  [[nodiscard]] double start_threshold_deg() const { return window_deg + lsb_deg; }
};

/// The seed's movement-window controller for one axis, with soft start and stop.
///
/// At rest the axis waits until |target − position| exceeds L2. It then runs — at full speed while
/// the error exceeds L1 = 3°, at tracking speed inside — towards a goal, and ramps to a stop within
/// 1 LSB of it. The seed's goal is the target itself, so a steadily moving target restarts the
/// motor every L2 of travel. With `lead` and a moving target, the goal is placed one window beyond
/// the target in the direction it moves, and the move ends when the reading reaches or passes it:
/// the target then drifts across the whole window (and the count of quantization) before the next
/// start, halving the starts (relay contacts and gears wear per start) for the same maximum error,
/// and letting a coarse encoder's moves span more than one count.
///
/// Deceleration is planned so the axis neither overshoots nor hunts: the commanded speed is the
/// least of the zone speed, K·d with K = 1/(4τ) (critical damping of a first-order motor under
/// position feedback), and √(2·a·d) with a the ramp's acceleration, plus the target's own rate
/// (feed-forward, so a moving goal is reached instead of chased). A move in the other direction
/// than the last one first has to take up the gear play, during which the shaft (and its encoder)
/// stands still: the play is added to the distance the speed is planned on until the commanded
/// motion has covered it, so the axis does not creep through it at final-approach speed. The
/// stiction is compensated (duty = min_duty + (1 − min_duty)·v/v_max) so that slow final approach
/// speeds still turn the motor; the duty changes by at most dt/ramp_s per tick (soft start and soft
/// stop).
class AxisController {
 public:
  explicit AxisController(const AxisControlConfig& config) : config_(config) {}

  /// One control tick. `target_rate_deg_s` is how fast the target moves (for the lead; 0 for a
  /// fixed target). Returns the duty to apply.
  double update(double target_deg, double position_deg, double target_rate_deg_s, double dt_s);

  /// Open loop (the direction test): the duty goes to `wanted` through the soft start, whatever
  /// the reading. Returns the duty to apply.
  double drive_open(double wanted, double dt_s);

  /// Drops the duty to zero at once and forgets the move (safety stops: no soft ramp).
  void halt();

  [[nodiscard]] double duty() const { return duty_; }
  [[nodiscard]] bool moving() const { return moving_; }
  /// Moves started since construction (each is a motor start from rest).
  [[nodiscard]] std::uint64_t starts() const { return starts_; }
  [[nodiscard]] const AxisControlConfig& config() const { return config_; }

 private:
  [[nodiscard]] bool is_leading(double target_rate_deg_s) const;
  [[nodiscard]] double goal_deg(double target_deg, double target_rate_deg_s) const;
  [[nodiscard]] double approach_speed_deg_s(double error_deg, double distance_deg) const;
  double slew_duty(double wanted, double dt_s);

  AxisControlConfig config_;
  double duty_ = 0.0;
  bool moving_ = false;
  double move_direction_ = 0.0;   ///< sign of the goal distance when the present move started
  double direction_ = 0.0;        ///< of the present or last move: +1, −1, 0 before the first
  double takeup_left_deg_ = 0.0;  ///< play still to take up in the present direction
  std::uint64_t starts_ = 0;
};

}  // namespace azt::control
