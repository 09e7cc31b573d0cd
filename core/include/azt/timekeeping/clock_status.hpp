#pragma once
// Whether the station's clock can be trusted (docs/time.md): what chronyd says, what the kernel
// says, and how old the reading is. Pure: the Linux side reads chronyc, adjtimex and /dev/rtc0
// off the event loop and hands the reading here with the loop's monotonic time. Unsynchronised
// is a banner, never a stop: the RTC holds time, and pointing with a clock a second off is still
// far better than not pointing.

#include <optional>
#include <string>
#include <vector>

#include "azt/timekeeping/chrony_report.hpp"

namespace azt::timekeeping {

/// One look at the clock.
struct ClockReading {
  double read_at_s = 0.0;                  ///< the caller's monotonic clock when it came back
  std::optional<ChronyTracking> tracking;  ///< none: chronyd did not answer
  std::string chrony_error;                ///< why there is no tracking report
  std::vector<ChronySource> sources;
  std::optional<bool> kernel_synced;  ///< adjtimex's verdict (none: not asked or not known)
  bool rtc_present = false;           ///< a battery-backed clock to hold time across power cuts
};

struct ClockStatus {
  bool synced = false;         ///< the clock can be trusted (assess_clock)
  bool chrony_synced = false;  ///< chronyd follows a source (its own local clock does not count)
  std::string reason;          ///< empty when synced; otherwise why not, for the banner
};

/// chronyd's refid for its own clock (the `local` directive): 127.127.1.1.
inline constexpr const char* kLocalRefIdHex = "7F7F0101";

/// The verdict on `reading` (none: never read) at `now_s`: a reading older than stale_after_s
/// is no reading (the probe itself has stopped). Synced: chronyd follows a real source and the
/// kernel does not disagree, or chronyd does not answer and the kernel says the clock is
/// synchronised (another NTP client keeps it).
ClockStatus assess_clock(const std::optional<ClockReading>& reading, double now_s,
                         double stale_after_s);

}  // namespace azt::timekeeping
