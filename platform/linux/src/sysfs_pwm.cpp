#include "azt/linux/sysfs_pwm.hpp"

#include "azt/linux/crash_safe_outputs.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>

namespace azt::linux_os {
namespace {

bool is_directory(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

}  // namespace

Result<bool> write_sysfs(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) return fail("open " + path + ": " + std::strerror(errno));
  const ssize_t n = ::write(fd, text.data(), text.size());
  const int err = errno;
  ::close(fd);
  if (n != static_cast<ssize_t>(text.size())) {
    return fail("write '" + text + "' to " + path + ": " +
                (n < 0 ? std::strerror(err) : "short write"));
  }
  return true;
}

Result<SysfsPwm> SysfsPwm::open(const std::string& chip_dir, unsigned channel,
                                double frequency_hz) {
  if (!std::isfinite(frequency_hz) || frequency_hz < 10.0 || frequency_hz > 100000.0) {
    return fail("PWM frequency must be 10 Hz to 100 kHz");
  }
  if (!is_directory(chip_dir))
    return fail(chip_dir + ": no such PWM chip (is the overlay loaded?)");
  const std::string dir = chip_dir + "/pwm" + std::to_string(channel);
  if (!is_directory(dir)) {
    if (auto r = write_sysfs(chip_dir + "/export", std::to_string(channel)); !r) return r.error();
    // The kernel creates pwmN at once; udev may take a moment to make it writable to group
    // azeltrack (debian/azeltrack.udev).
    for (int i = 0; i < 50 && ::access((dir + "/period").c_str(), W_OK) != 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (!is_directory(dir)) return fail(dir + " did not appear after export");
  }
  const auto period_ns = static_cast<std::uint64_t>(std::llround(1e9 / frequency_hz));
  // duty ≤ period at every step: zero the duty before changing the period.
  for (const auto& [file, value] :
       {std::pair{"duty_cycle", std::string("0")}, std::pair{"period", std::to_string(period_ns)},
        std::pair{"duty_cycle", std::string("0")}, std::pair{"enable", std::string("1")}}) {
    if (auto r = write_sysfs(dir + "/" + file, value); !r) return r.error();
  }
  // Should the process crash, the channel must not keep the duty it had (crash_safe_outputs.hpp).
  (void)register_crash_write(dir + "/duty_cycle", "0");
  (void)register_crash_write(dir + "/enable", "0");
  SysfsPwm pwm(dir, period_ns);
  pwm.duty_ns_ = 0;
  return pwm;
}

Result<bool> SysfsPwm::set_duty(double fraction) {
  if (!std::isfinite(fraction)) fraction = 0.0;
  const auto duty = static_cast<std::uint64_t>(
      std::llround(std::clamp(fraction, 0.0, 1.0) * static_cast<double>(period_ns_)));
  if (duty_ns_ == duty) return true;
  auto r = write_sysfs(dir_ + "/duty_cycle", std::to_string(duty));
  if (!r) {
    duty_ns_.reset();  // unknown now: write again next time
    return r;
  }
  duty_ns_ = duty;
  return true;
}

Result<bool> SysfsPwm::set_rate(double frequency_hz, double fraction) {
  if (!std::isfinite(frequency_hz) || frequency_hz < 1.0 || frequency_hz > 1e6) {
    return fail("a step rate must be 1 Hz to 1 MHz");
  }
  const auto period_ns = static_cast<std::uint64_t>(std::llround(1e9 / frequency_hz));
  if (period_ns != period_ns_) {
    if (!duty_ns_ || *duty_ns_ > period_ns) {
      if (auto r = set_duty(0.0); !r) return r;
    }
    if (auto r = write_sysfs(dir_ + "/period", std::to_string(period_ns)); !r) {
      duty_ns_.reset();
      return r;
    }
    period_ns_ = period_ns;
  }
  return set_duty(fraction);
}

Result<bool> SysfsPwm::disable() {
  duty_ns_.reset();
  if (auto r = write_sysfs(dir_ + "/duty_cycle", "0"); !r) return r;
  return write_sysfs(dir_ + "/enable", "0");
}

}  // namespace azt::linux_os
