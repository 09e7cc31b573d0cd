#include "daemon/rate_limited_log.hpp"

#include <spdlog/spdlog.h>

namespace azt::app {

void RateLimitedLog::info(const std::string& key, const std::string& line, double now_s) {
  auto& b = buckets_[key];
  if (now_s - b.window_start_s > 60.0) {
    if (b.suppressed > 0) spdlog::info("{}: {} similar messages suppressed", key, b.suppressed);
    b = Bucket{now_s, 0, 0};
  }
  if (++b.sent <= kBurst) {
    spdlog::info("{}", line);
  } else {
    ++b.suppressed;
  }
}

}  // namespace azt::app
