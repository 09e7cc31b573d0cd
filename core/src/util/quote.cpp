#include "azt/util/quote.hpp"

#include <algorithm>

namespace azt {

std::string quote(std::string_view text, std::size_t max_chars) {
  std::string out;
  out.reserve(std::min(text.size(), max_chars) + 5);
  out += '"';
  out += text.substr(0, max_chars);
  if (text.size() > max_chars) out += "...";
  out += '"';
  return out;
}

}  // namespace azt
