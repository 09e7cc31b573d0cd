#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace azt {

/// User input quoted for an error message, cut to `max_chars` (then ending in "...") so a
/// pasted megabyte never ends up in a log line.
std::string quote(std::string_view text, std::size_t max_chars = 64);

}  // namespace azt
