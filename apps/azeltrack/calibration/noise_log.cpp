#include "calibration/noise_log.hpp"

#include <deque>
#include <fstream>

namespace azt::app {

nlohmann::json read_noise_log(const std::string& path, std::size_t max_entries) {
  std::ifstream in(path);
  std::deque<nlohmann::json> newest;
  std::size_t bad = 0;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    auto record = nlohmann::json::parse(line, nullptr, false);
    if (record.is_discarded() || !record.is_object()) {
      ++bad;
      continue;
    }
    newest.push_front(std::move(record));
    if (newest.size() > max_entries) newest.pop_back();
  }
  nlohmann::json entries = nlohmann::json::array();
  for (auto& r : newest) entries.push_back(std::move(r));
  return {{"entries", entries}, {"bad_lines", bad}};
}

}  // namespace azt::app
