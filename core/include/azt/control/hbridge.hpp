#pragma once
// An IBT-2 / BTS7960 H-bridge per axis (the seed's "LDMOS power modules"): two PWM inputs, RPWM
// drives one way and LPWM the other, and an enable pair. The controller asks for a signed duty
// (its ramps already make starts and stops soft); this layer only guarantees that the bridge is
// never reversed under load: when the sign changes, both PWMs go to zero, and the other side is
// driven only after `dead_time_s` with both at zero, so the motor has stopped pushing and the
// two half-bridges never conduct together. Pure; time is a parameter.

#include <optional>

namespace azt::control {

struct HBridgeOutputs {
  double rpwm = 0.0;    ///< 0..1, positive duty (clockwise / up)
  double lpwm = 0.0;    ///< 0..1, negative duty
  bool enable = false;  ///< R_EN and L_EN: off when both PWMs are zero for good (disable())
};

class HBridge {
 public:
  explicit HBridge(double dead_time_s = 0.1) : dead_time_s_(dead_time_s) {}

  /// The outputs for the controller's signed duty (−1..+1, clamped) at `now_s`.
  HBridgeOutputs drive(double now_s, double duty);
  /// Everything off now (faults, E-stop, shutdown); the next drive() waits the dead time.
  HBridgeOutputs disable(double now_s);

  [[nodiscard]] double dead_time_s() const { return dead_time_s_; }

 private:
  double dead_time_s_;
  int direction_ = 0;  ///< the side driven now: +1, −1, 0 (both PWMs zero)
  int last_side_ = 0;  ///< the side driven before the present zero (2: unknown, after disable)
  bool disabled_ = false;
  std::optional<double> zero_since_s_;  ///< when both PWMs last became zero
};

}  // namespace azt::control
