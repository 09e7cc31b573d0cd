#include "azt/linux/systemd_notify.hpp"

#include <systemd/sd-daemon.h>

#include <cstdint>

namespace azt::linux_os {

SystemdNotifier::SystemdNotifier() {
  std::uint64_t usec = 0;
  if (sd_watchdog_enabled(0, &usec) > 0 && usec > 0) {
    watchdog_period_s_ = static_cast<double>(usec) / 2e6;
  }
}

void SystemdNotifier::ready(const std::string& status) const {
  sd_notify(0, ("READY=1\nSTATUS=" + status).c_str());
}

void SystemdNotifier::status(const std::string& status) const {
  sd_notify(0, ("STATUS=" + status).c_str());
}

void SystemdNotifier::stopping() const { sd_notify(0, "STOPPING=1"); }

void SystemdNotifier::watchdog() const {
  if (watchdog_period_s_) sd_notify(0, "WATCHDOG=1");
}

}  // namespace azt::linux_os
