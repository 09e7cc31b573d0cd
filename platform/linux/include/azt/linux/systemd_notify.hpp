#pragma once
// sd_notify(3) for running under systemd (Type=notify, WatchdogSec=): READY once the servers
// listen, WATCHDOG from the control tick, STOPPING on shutdown. Outside systemd every call is a
// no-op.

#include <optional>
#include <string>

namespace azt::linux_os {

class SystemdNotifier {
 public:
  /// Reads the watchdog interval systemd asks for (WATCHDOG_USEC), if any.
  SystemdNotifier();

  void ready(const std::string& status) const;
  void status(const std::string& status) const;
  void stopping() const;
  /// Pets the watchdog; call from the control tick (so a stuck tick lets systemd restart us).
  void watchdog() const;
  /// How often watchdog() should be called: half the interval systemd gave, or nullopt.
  [[nodiscard]] std::optional<double> watchdog_period_s() const { return watchdog_period_s_; }

 private:
  std::optional<double> watchdog_period_s_;
};

}  // namespace azt::linux_os
