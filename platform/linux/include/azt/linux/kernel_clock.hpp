#pragma once
// What the kernel says about the system clock (docs/time.md): adjtimex(2) asked to change nothing
// (modes 0, allowed to any user) reports whether an NTP daemon keeps the clock synchronised,
// and the error bounds it was given. And whether a battery-backed RTC is there to hold time.

#include <string>

#include "azt/util/result.hpp"

namespace azt::linux_os {

struct KernelClock {
  bool synchronised = false;  ///< not TIME_ERROR and STA_UNSYNC clear
  double max_error_s = 0.0;   ///< the kernel's maximum error bound
  double est_error_s = 0.0;   ///< its estimated error
};

/// Reads the kernel's clock state; changes nothing.
Result<KernelClock> read_kernel_clock();

/// True when `path` (normally /dev/rtc0) is a character device.
bool rtc_present(const std::string& path);

}  // namespace azt::linux_os
