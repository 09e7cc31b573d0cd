#include "station/recent_events.hpp"

#include "azt/astro/time_scales.hpp"
#include "azt/util/valid_utf8.hpp"

namespace azt::app {

void RecentEvents::add(double unix_s, std::string text, std::string merge_key) {
  text = valid_utf8(text);  // a client's name or bytes may be anything
  if (merge_key.empty()) merge_key = text;
  if (!events_.empty() && events_.back().key == merge_key) {
    ++events_.back().count;
    events_.back().last_s = unix_s;
    events_.back().text = std::move(text);
    return;
  }
  events_.push_back(Event{unix_s, unix_s, std::move(text), std::move(merge_key), 1});
  while (events_.size() > kMaxEvents) events_.pop_front();
}

nlohmann::json RecentEvents::to_json() const {
  nlohmann::json out = nlohmann::json::array();
  for (auto it = events_.rbegin(); it != events_.rend(); ++it) {
    out.push_back({{"utc", astro::format_iso8601_utc_unix(it->last_s)},
                   {"text", it->text},
                   {"count", it->count}});
  }
  return out;
}

}  // namespace azt::app
