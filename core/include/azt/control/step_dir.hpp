#pragma once
// A stepper motor on a step/direction driver (DRV8825, TB6600, DM542 …; docs/hardware.md,
// "Steppers"): each pulse on STEP is one (micro)step and DIR chooses the way. The controller's
// signed duty is a step rate, a fraction of `max_step_hz`; this layer makes it a rate the motor
// can follow.
//
// A stepper asked to change its rate faster than its torque can accelerate the rotor loses steps
// or stalls, which is why step generators ramp (D. Austin, "Generate stepper-motor speed profiles
// in real time", Embedded Systems Programming, January 2005; AccelStepper's acceleration). So:
// - within the pull-in band (`start_hz`) the motor starts, stops and follows at once;
// - above it the rate changes by at most `accel_hz_s` per second;
// - DIR changes only at a standstill, and no step is sent in the tick it changes, so the driver
//   has a whole tick of set-up (a DRV8825 needs 650 ns before a STEP edge: TI SLVSA73F, 7.6).
// A reversal therefore ramps down, stops, turns DIR, and ramps up the other way.
//
// The loop is closed on the axis's encoder or pot, as for every other drive: a lost step is a
// reading that lags, which the controller makes up and the supervisor's stall check catches.
// Pure; time is a parameter.

#include <optional>

#include "azt/util/result.hpp"

namespace azt::control {

struct StepDirConfig {
  /// Slower than this no pulses are made (a sysfs PWM period of a second at most): the closed
  /// loop then moves the axis in short bursts, as it moves a relay axis.
  static constexpr double kMinStepHz = 1.0;

  double max_step_hz = 2000.0;  ///< duty 1: the axis's full rate × steps per degree
  double start_hz = 200.0;      ///< the pull-in rate: started and stopped at without a ramp
  double accel_hz_s = 4000.0;   ///< the largest change of rate per second above it

  /// Finite and positive, start_hz ≤ max_step_hz (0 ramps every start from standstill).
  static Result<StepDirConfig> make(double max_step_hz, double start_hz, double accel_hz_s);
};

struct StepDirOutputs {
  double step_hz = 0.0;  ///< the pulse rate on STEP; 0: no pulses
  int direction = 0;     ///< DIR: +1 clockwise / up, −1 the other way, 0 before the first move
  bool enable = false;   ///< the driver's ENABLE: off after disable(), on while driven
};

class StepDir {
 public:
  explicit StepDir(const StepDirConfig& config) : config_(config) {}

  /// The outputs for the controller's signed duty (−1…+1, clamped) at `now_s`.
  StepDirOutputs drive(double now_s, double duty);
  /// No pulses and the driver disabled now (faults, E-stop, shutdown); the next drive() starts
  /// from a standstill.
  StepDirOutputs disable(double now_s);

 private:
  [[nodiscard]] double next_rate(double wanted_hz, double dt_s) const;

  StepDirConfig config_;
  std::optional<double> last_s_;  ///< the last call's time; none before the first
  double rate_hz_ = 0.0;          ///< unsigned: the way is direction_
  int direction_ = 0;
};

}  // namespace azt::control
