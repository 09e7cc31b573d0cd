#include "azt/util/format_number.hpp"

#include <array>
#include <charconv>

namespace azt {

std::string format_number(double value) {
  std::array<char, 32> buf{};
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), value);
  return ec == std::errc{} ? std::string(buf.data(), end) : std::string("?");
}

std::string format_fixed(double value, int decimals) {
  std::array<char, 64> buf{};
  const auto [end, ec] =
      std::to_chars(buf.data(), buf.data() + buf.size(), value, std::chars_format::fixed, decimals);
  return ec == std::errc{} ? std::string(buf.data(), end) : format_number(value);
}

}  // namespace azt
