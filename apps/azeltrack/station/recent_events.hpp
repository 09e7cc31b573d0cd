#pragma once
// What the operator should know happened lately, for the console: every refusal a
// client was given (a target below the elevation limit, a move while a fault is latched, a
// position asked for while the sensors are stale) and every change of who commands the antenna.
// A client repeating the same refused command makes one entry with a count, not a flood.

#include <cstddef>
#include <deque>
#include <string>

#include <nlohmann/json.hpp>

namespace azt::app {

class RecentEvents {
 public:
  static constexpr std::size_t kMaxEvents = 20;

  /// `text` is "who: what" as the daemon logs it; `unix_s` is UTC seconds. The newest entry is
  /// counted again, with `text` as its latest words, when `merge_key` is the same (by default the
  /// text itself): a program sending a new position every second makes one line, not a flood.
  void add(double unix_s, std::string text, std::string merge_key = {});
  /// Newest first: [{"utc", "text", "count"}].
  [[nodiscard]] nlohmann::json to_json() const;

 private:
  struct Event {
    double first_s = 0.0;
    double last_s = 0.0;
    std::string text;
    std::string key;
    std::size_t count = 1;
  };
  std::deque<Event> events_;  ///< oldest first
};

}  // namespace azt::app
