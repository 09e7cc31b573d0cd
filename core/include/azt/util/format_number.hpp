#pragma once

#include <string>

namespace azt {

/// Shortest text that reads back as the same double (std::to_chars: locale-free, no exponent
/// surprises from printf). "nan"/"inf" for non-finite values. For messages and labels.
std::string format_number(double value);

/// Fixed-point text with `decimals` digits after the point ("0.012"), locale-free; "nan"/"inf"
/// for non-finite values. For messages.
std::string format_fixed(double value, int decimals);

}  // namespace azt
