#include "azt/timekeeping/clock_status.hpp"

namespace azt::timekeeping {
namespace {

std::string chrony_verdict(const ClockReading& r) {
  if (!r.tracking) return "chronyd does not answer: " + r.chrony_error;
  if (!r.tracking->synchronised()) return "chrony is not synchronised: no usable time source";
  if (r.tracking->ref_id_hex == kLocalRefIdHex) {
    return "chrony holds time on its own clock: no GPS and no NTP server";
  }
  return "";
}

}  // namespace

ClockStatus assess_clock(const std::optional<ClockReading>& reading, double now_s,
                         double stale_after_s) {
  ClockStatus s;
  if (!reading) {
    s.reason = "the clock has not been checked yet";
    return s;
  }
  if (now_s - reading->read_at_s > stale_after_s) {
    s.reason = "the clock's state is stale: the last check is too old";
    return s;
  }
  s.reason = chrony_verdict(*reading);
  s.chrony_synced = s.reason.empty();
  if (s.chrony_synced && reading->kernel_synced == false) {
    s.reason = "the kernel says the clock is not synchronised";
  }
  // Without chronyd, another NTP client (systemd-timesyncd, ntpd) may keep the clock: the
  // kernel's flag is then the only word, and it is enough.
  if (!reading->tracking && reading->kernel_synced == true) s.reason.clear();
  s.synced = s.reason.empty();
  return s;
}

}  // namespace azt::timekeeping
