#include "console/query_string.hpp"

#include <algorithm>

namespace azt::app {

std::optional<std::string> query_value(const std::string& query, std::string_view key) {
  std::size_t start = 0;
  while (start <= query.size()) {
    const auto end = std::min(query.find('&', start), query.size());
    const std::string_view item(query.data() + start, end - start);
    if (item.size() > key.size() && item.substr(0, key.size()) == key && item[key.size()] == '=') {
      return std::string(item.substr(key.size() + 1));
    }
    start = end + 1;
  }
  return std::nullopt;
}

}  // namespace azt::app
