#pragma once

#include <optional>
#include <string_view>

namespace azt {

/// Parses a whole string as a finite double, locale-free (std::from_chars).
/// Rejects empty input, leading/trailing junk or spaces, NaN and infinities.
std::optional<double> parse_finite_double(std::string_view text);

}  // namespace azt
