#include "azt/util/parse_number.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace azt {

std::optional<double> parse_finite_double(std::string_view text) {
  if (text.empty()) return std::nullopt;
  // from_chars rejects a leading '+', which people type; accept exactly one, and no sign after it
  // ("+-5" must not read as -5).
  if (text.front() == '+') {
    text.remove_prefix(1);
    if (text.empty() || text.front() == '+' || text.front() == '-') return std::nullopt;
  }
  double value = 0.0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc{} || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace azt
