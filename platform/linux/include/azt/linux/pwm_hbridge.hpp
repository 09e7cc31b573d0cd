#pragma once
// An IBT-2 / BTS7960 H-bridge on two sysfs PWM channels (RPWM, LPWM): the core's HBridge decides
// (one side at a time, dead time before a reversal), this writes it. The enable lines (R_EN,
// L_EN) are wired high or come with the GPIO adapter; disabling zeroes and disables both PWMs.

#include <string>

#include "azt/control/hbridge.hpp"
#include "azt/linux/sysfs_pwm.hpp"

namespace azt::linux_os {

struct PwmHBridgeConfig {
  std::string chip_dir = "/sys/class/pwm/pwmchip0";
  unsigned rpwm_channel = 0;
  unsigned lpwm_channel = 1;
  double frequency_hz = 1000.0;
  double dead_time_s = 0.1;
};

class PwmHBridge {
 public:
  /// Opens both channels at zero duty; fails naming the chip or channel.
  static Result<PwmHBridge> open(const PwmHBridgeConfig& config);

  /// The controller's signed duty at `now_s`. A failed write disables both channels and is
  /// returned (the caller latches a fault: the drive is off).
  Result<bool> apply(double now_s, double duty);
  Result<bool> disable(double now_s);

 private:
  PwmHBridge(SysfsPwm r, SysfsPwm l, double dead_time_s)
      : rpwm_(std::move(r)), lpwm_(std::move(l)), bridge_(dead_time_s) {}

  SysfsPwm rpwm_;
  SysfsPwm lpwm_;
  control::HBridge bridge_;
};

}  // namespace azt::linux_os
