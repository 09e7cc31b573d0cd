#include "azt/linux/kernel_clock.hpp"

#include <sys/stat.h>
#include <sys/timex.h>

#include <cerrno>
#include <cstring>

namespace azt::linux_os {

Result<KernelClock> read_kernel_clock() {
  timex tx{};
  tx.modes = 0;  // read only
  const int state = ::adjtimex(&tx);
  if (state < 0) return fail(std::string("adjtimex: ") + std::strerror(errno));
  constexpr double kMicro = 1e-6;
  return KernelClock{state != TIME_ERROR && (tx.status & STA_UNSYNC) == 0,
                     static_cast<double>(tx.maxerror) * kMicro,
                     static_cast<double>(tx.esterror) * kMicro};
}

bool rtc_present(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

}  // namespace azt::linux_os
