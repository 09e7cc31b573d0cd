#pragma once

#include <cstdint>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::sim {

/// One simulated antenna axis. Angles are axis (mount) degrees on the antenna side of the gears;
/// the "motor" is the drive side of the last gear stage, expressed in the same axis degrees.
/// Duty is signed, −1..+1, positive towards increasing angle (control/axis_controller.hpp).
struct AxisParams {
  double max_rate_deg_s = 1.5;     ///< axis rate at full duty (reference plant: az 1.5, el 1.0)
  double time_constant_s = 0.3;    ///< first-order motor speed response
  double backlash_deg = 0.05;      ///< total play between motor and antenna shaft
  double stiction_duty = 0.1;      ///< |duty| at or below this does not turn the motor
  std::uint8_t encoder_bits = 12;  ///< absolute encoder on the antenna shaft, 9–16 (EncoderHub)
  double start_deg = 0.0;
  double min_deg = 0.0;  ///< end stops, mount degrees (az may run past 360, el below 0)
  double max_deg = 360.0;

  /// Checks every field (τ > 0, rate > 0, 9–16 bits, 0 ≤ stiction < 1, backlash ≥ 0,
  /// min < max, start within the stops, all finite); errors name the field.
  [[nodiscard]] Result<AxisParams> validate() const;
};

/// Faults the plant can be told to have. Link faults (lost or corrupted frames) belong to the
/// simulated EncoderHub link, not here.
enum class AxisFaultKind : std::uint8_t {
  FrozenShaft,    ///< the antenna shaft does not move; the motor turns (slipping coupling, ice)
  ReversedMotor,  ///< motor wired the wrong way round: positive duty drives negative
  EncoderOffset,  ///< every reading off by `counts` (a slipped encoder coupling) until cleared
  EncoderGlitch,  ///< readings off by `counts` until the next step() (one bad sample)
};

std::string_view to_string(AxisFaultKind kind);

struct AxisFault {
  AxisFaultKind kind = AxisFaultKind::FrozenShaft;
  std::int32_t counts = 0;  ///< EncoderOffset / EncoderGlitch only
};

/// A duty-driven axis in virtual time.
///
/// Model, per step(duty, dt_s) with the duty held for dt_s (zero-order hold):
///  1. Stiction as a dead zone: |duty| ≤ s gives no torque; above it the commanded rate is
///     max_rate·(|duty| − s)/(1 − s), signed. Full duty is full rate, and the controller's
///     compensation duty = s + (1 − s)·v/v_max (axis_controller.hpp) is its exact inverse. (A
///     break-away model, where more duty starts than keeps turning, would add memory for little.)
///  2. The motor rate follows the commanded rate with time constant τ, discretised exactly:
///     ω ← ω_c + (ω − ω_c)·e^(−dt/τ), and the motor angle by the exact integral of that
///     exponential. Any dt is stable and the result does not depend on how a span is cut into
///     steps (the play, the stops and faults act on the motor angle at step ends: keep dt well
///     below backlash / max_rate if reversals within a step matter).
///  3. The shaft follows the motor through a play of width b (the classic backlash operator):
///     it moves only while the motor pushes on one side of the gap, staying within b/2 of it.
///     At construction the motor sits in the middle of the play, so the first move of either
///     direction loses b/2 and every reversal loses b.
///  4. End stops clamp the shaft to [min, max]; the motor is stopped against the shaft
///     (min − b/2, max + b/2) and its rate towards the stop is zeroed.
///  5. The absolute encoder reads the shaft: raw = floor(wrap360(shaft)/360 · 2^bits) mod 2^bits
///     for both axes, so an elevation of −0.05° reads 2^bits − 1 (the EncoderHub's reader maps
///     readings above 270° back to negative elevations).
class AxisPlant {
 public:
  /// Precondition: params.validate().ok() (use make() when unsure).
  explicit AxisPlant(const AxisParams& params);
  static Result<AxisPlant> make(const AxisParams& params);

  /// Advances by dt_s with `duty` held (clamped to ±1; NaN counts as 0). dt_s ≤ 0 or non-finite
  /// leaves the state as it is. Ends any EncoderGlitch.
  void step(double duty, double dt_s);

  /// The axis is moved by another model (a linear actuator, actuator_dish_plant.hpp): its shaft
  /// and motor are at `shaft_deg`, turning at `rate_deg_s`, so its encoder and every reader of the
  /// plant's truth see that model's angle.
  void follow(double shaft_deg, double rate_deg_s) {
    shaft_deg_ = shaft_deg;
    motor_deg_ = shaft_deg;
    motor_rate_deg_s_ = rate_deg_s;
  }

  [[nodiscard]] double shaft_deg() const { return shaft_deg_; }
  [[nodiscard]] double motor_deg() const { return motor_deg_; }
  [[nodiscard]] double motor_rate_deg_s() const { return motor_rate_deg_s_; }
  [[nodiscard]] std::uint16_t encoder_raw() const;
  [[nodiscard]] std::uint8_t encoder_bits() const { return params_.encoder_bits; }
  /// One encoder count in degrees: 360/2^bits (seed 000 appendix: 12 bits, 0.0879°).
  [[nodiscard]] double lsb_deg() const;
  [[nodiscard]] bool at_min_stop() const { return shaft_deg_ <= params_.min_deg; }
  [[nodiscard]] bool at_max_stop() const { return shaft_deg_ >= params_.max_deg; }
  [[nodiscard]] bool at_stop() const { return at_min_stop() || at_max_stop(); }
  [[nodiscard]] const AxisParams& params() const { return params_; }

  /// Starts a fault; injecting an encoder fault again replaces its count.
  void inject(const AxisFault& fault);
  /// Ends one kind of fault. Ending FrozenShaft re-engages the motor where the shaft stands (the
  /// coupling grips again), so the shaft does not jump by the distance the motor ran meanwhile.
  void clear(AxisFaultKind kind);
  void clear_faults();
  [[nodiscard]] bool has_fault(AxisFaultKind kind) const;

 private:
  [[nodiscard]] double commanded_rate_deg_s(double duty) const;
  [[nodiscard]] double decay_for(double dt_s);
  void apply_stops();
  void apply_backlash();

  AxisParams params_;
  double motor_deg_ = 0.0;
  double motor_rate_deg_s_ = 0.0;
  double shaft_deg_ = 0.0;
  double cached_dt_s_ = 0.0;  ///< e^(−dt/τ) is cached: control loops step with a fixed dt
  double cached_decay_ = 1.0;
  bool frozen_ = false;
  bool reversed_ = false;
  std::int32_t offset_counts_ = 0;
  std::int32_t glitch_counts_ = 0;
};

}  // namespace azt::sim
