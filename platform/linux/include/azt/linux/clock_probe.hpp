#pragma once
// One look at the station's clock (docs/time.md): chronyd's tracking and sources through chronyc
// (`-c` for CSV, `-n` so no name lookup can stall it, `-m` for both in one run), the kernel's
// adjtimex verdict and the RTC. Blocks for as long as chronyc takes (bounded), so it runs on a
// worker thread; the core's assess_clock judges the reading.

#include <string>

#include "azt/timekeeping/clock_status.hpp"
#include "azt/util/result.hpp"

namespace azt::linux_os {

struct ClockProbeConfig {
  std::string chronyc = "chronyc";  ///< the program
  std::string chrony_host;  ///< chronyc -h: a command socket path or a host ("": its default)
  double timeout_s = 5.0;
  std::string rtc_device = "/dev/rtc0";
};

/// Reads the clock now (the caller stamps read_at_s on its own clock). chronyd not answering is a
/// reading (with chrony_error), not a failure.
timekeeping::ClockReading probe_clock(const ClockProbeConfig& config);

/// `chronyc reload sources`: chronyd re-reads its sourcedir files. Needs chronyd's Unix command
/// socket (root or the _chrony group); the error says what chronyc said.
Result<bool> reload_chrony_sources(const ClockProbeConfig& config);

}  // namespace azt::linux_os
