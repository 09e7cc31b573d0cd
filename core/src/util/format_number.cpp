#include "azt/util/format_number.hpp"

#include <array>
#include <charconv>

namespace azt {

std::string format_number(double value) {
  std::array<char, 32> buf{};
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), value);
  return ec == std::errc{} ? std::string(buf.data(), end) : std::string("?");
}

}  // namespace azt
