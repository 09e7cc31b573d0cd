#include "hamlib_process.hpp"

// Hamlib's C headers are not clean under -Wpedantic/-Wconversion; keep them out of our warnings.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#include <hamlib/rig.h>
#pragma GCC diagnostic pop

namespace azt::linux_os {

std::mutex& hamlib_global_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::string hamlib_status_text(int rc) {
  std::string text;
  {
    const std::lock_guard lock(hamlib_global_mutex());
    const char* reason = rigerror2(rc);
    text = reason != nullptr ? reason : "unknown error";
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
    text.pop_back();
  }
  return text + " (Hamlib status " + std::to_string(rc) + ")";
}

bool is_hamlib_link_error(int rc) {
  switch (-rc) {
    case RIG_ETIMEOUT:
    case RIG_EIO:
    case RIG_EPROTO:
    case RIG_EINTERNAL:
    case RIG_BUSERROR:
    case RIG_BUSBUSY:
    case RIG_EPOWER:
      return true;
    default:
      return false;
  }
}

void quiet_hamlib() {
  const std::lock_guard lock(hamlib_global_mutex());
  rig_set_debug(RIG_DEBUG_NONE);
}

}  // namespace azt::linux_os
