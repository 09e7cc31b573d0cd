#pragma once
// A PWM channel through the kernel's sysfs interface (Documentation/ABI/testing/sysfs-class-pwm,
// on a Raspberry Pi the pwm-2chan overlay): `CHIP/export` takes the channel number, then
// `CHIP/pwmN/period`, `duty_cycle` (nanoseconds) and `enable` (0/1) drive it. The chip directory
// is a parameter, so tests run against a directory laid out the same way.

#include <cstdint>
#include <optional>
#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

class SysfsPwm {
 public:
  /// Exports the channel (unless already exported), sets the period for `frequency_hz` with the
  /// duty at zero, and enables it. Fails naming the file and the reason (no such chip, a
  /// channel that does not export, permissions).
  static Result<SysfsPwm> open(const std::string& chip_dir, unsigned channel, double frequency_hz);

  /// 0..1 of the period; written only when it changes.
  Result<bool> set_duty(double fraction);
  /// A new frequency (1 Hz to 1 MHz) with the duty at `fraction` of the new period: a step/dir
  /// driver's STEP input, whose pulse rate is the step rate. The period is written only when it
  /// changes, the duty zeroed first when it would not fit the new period (the kernel refuses a
  /// duty longer than the period).
  Result<bool> set_rate(double frequency_hz, double fraction);
  /// Duty zero, then disabled.
  Result<bool> disable();

  [[nodiscard]] const std::string& dir() const { return dir_; }
  [[nodiscard]] std::uint64_t period_ns() const { return period_ns_; }

 private:
  SysfsPwm(std::string dir, std::uint64_t period_ns)
      : dir_(std::move(dir)), period_ns_(period_ns) {}

  std::string dir_;  ///< CHIP/pwmN
  std::uint64_t period_ns_;
  std::optional<std::uint64_t> duty_ns_;  ///< last written
};

/// Writes `text` to a sysfs attribute (open, write, close; the kernel acts on the write).
Result<bool> write_sysfs(const std::string& path, const std::string& text);

}  // namespace azt::linux_os
