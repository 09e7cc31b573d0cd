#pragma once

#include <string>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::astro {

/// A Maidenhead (QTH) locator square: its centre and its size.
struct LocatorSquare {
  double lat_deg = 0.0;     ///< centre
  double lon_deg = 0.0;     ///< centre
  double height_deg = 0.0;  ///< latitude span of the square
  double width_deg = 0.0;   ///< longitude span of the square
};

/// Decodes a locator of 4, 6, 8 or 10 characters (field A–R, square 0–9, subsquare a–x,
/// extended square 0–9, extended subsquare a–x; case-insensitive), e.g. "FN06HE" →
/// 46.1875 N, 79.375 W. Error (naming the bad character and its position) on any other length
/// or character.
Result<LocatorSquare> decode_locator(std::string_view locator);

/// Encodes a position as a locator of `chars` characters (4, 6, 8 or 10): fields upper case,
/// subsquares lower case ("FN06he"). Latitude 90 and longitude 180 fall in the last square.
/// Error on a bad length or a coordinate out of range / not finite.
Result<std::string> encode_locator(double lat_deg, double lon_deg, int chars);

}  // namespace azt::astro
