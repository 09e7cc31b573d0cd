#pragma once
// The daemon's journal guard: a client reconnecting or re-sending in a loop cannot flood it.

#include <map>
#include <string>

namespace azt::app {

/// At most `burst` lines per key per minute; the rest are counted and summarised, so a client
/// reconnecting in a loop cannot flood the journal.
class RateLimitedLog {
 public:
  void info(const std::string& key, const std::string& line, double now_s);

 private:
  static constexpr int kBurst = 10;
  struct Bucket {
    double window_start_s = -1e9;
    int sent = 0;
    int suppressed = 0;
  };
  std::map<std::string, Bucket> buckets_;
};

}  // namespace azt::app
