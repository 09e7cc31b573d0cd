// Maidenhead locators, as used by radio amateurs (adopted by the IARU Region 1 VHF meeting,
// Brighton 1980), with the common 10-character extension: each pair splits the previous cell.
//
// Every pair divides longitude and latitude alike, so one integer grid serves both: the finest
// cell (extended subsquare, 1.25″ × 0.625″) is one unit, and the cells of each level span
//   field 57600, square 5760, subsquare 240, extended square 24, extended subsquare 1 units,
// with 1 unit = 1/2880° of longitude or 1/5760° of latitude. Integer arithmetic keeps the
// nesting exact: the 4-character locator of a point is always a prefix of its 10-character one.

#include "azt/astro/maidenhead.hpp"
#include "azt/util/format_number.hpp"
#include "azt/util/quote.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <system_error>

namespace azt::astro {

namespace {

struct Level {
  char first;            ///< lowest symbol ('A', '0' or 'a')
  int count;             ///< symbols on this level: 18, 10 or 24
  std::int64_t units;    ///< cell size of this level in finest-grid units
  const char* expected;  ///< for error messages
};

constexpr std::array<Level, 5> kLevels = {{
    {'A', 18, 57600, "a field letter A-R"},
    {'0', 10, 5760, "a square digit 0-9"},
    {'a', 24, 240, "a subsquare letter a-x"},
    {'0', 10, 24, "an extended-square digit 0-9"},
    {'a', 24, 1, "an extended-subsquare letter a-x"},
}};
constexpr double kUnitsPerLonDeg = 2880.0;
constexpr double kUnitsPerLatDeg = 5760.0;
constexpr std::int64_t kGridUnits = std::int64_t{18} * 57600;  ///< whole globe, both axes

bool valid_length(std::size_t n) { return n == 4 || n == 6 || n == 8 || n == 10; }

/// Symbol index of `c` on `level`, case-insensitive for letters; nullopt if not a symbol there.
std::optional<int> symbol_index(char c, const Level& level) {
  int index = c - level.first;
  if (level.first != '0' && (index < 0 || index >= level.count)) {
    index = c - (level.first == 'A' ? 'a' : 'A');  // the other case
  }
  if (index < 0 || index >= level.count) return std::nullopt;
  return index;
}

/// Finest-grid cell index of a coordinate already checked to lie in [0, span]; the far edge
/// (latitude 90, longitude 180) goes to the last cell.
std::int64_t grid_index(double offset_deg, double units_per_deg) {
  const double cell = std::floor(offset_deg * units_per_deg);
  if (cell >= static_cast<double>(kGridUnits)) return kGridUnits - 1;
  if (cell <= 0.0) return 0;
  return static_cast<std::int64_t>(cell);
}

}  // namespace

Result<LocatorSquare> decode_locator(std::string_view locator) {
  if (!valid_length(locator.size())) {
    return fail("locator " + quote(locator) + " has " + std::to_string(locator.size()) +
                " characters; a locator has 4, 6, 8 or 10");
  }
  std::int64_t lon_units = 0;
  std::int64_t lat_units = 0;
  for (std::size_t i = 0; i < locator.size(); ++i) {
    const Level& level = kLevels[i / 2];
    const auto index = symbol_index(locator[i], level);
    if (!index) {
      return fail("locator " + quote(locator) + ": character '" + std::string(1, locator[i]) +
                  "' at position " + std::to_string(i + 1) + " should be " + level.expected);
    }
    (i % 2 == 0 ? lon_units : lat_units) += *index * level.units;
  }
  const std::int64_t cell = kLevels[locator.size() / 2 - 1].units;
  // Centre = corner + half a cell, computed as (2 corner + cell) / 2 to stay in integers.
  LocatorSquare square;
  square.lon_deg = static_cast<double>(2 * lon_units + cell) / (2.0 * kUnitsPerLonDeg) - 180.0;
  square.lat_deg = static_cast<double>(2 * lat_units + cell) / (2.0 * kUnitsPerLatDeg) - 90.0;
  square.width_deg = static_cast<double>(cell) / kUnitsPerLonDeg;
  square.height_deg = static_cast<double>(cell) / kUnitsPerLatDeg;
  return square;
}

Result<std::string> encode_locator(double lat_deg, double lon_deg, int chars) {
  if (chars < 0 || !valid_length(static_cast<std::size_t>(chars))) {
    return fail("locator length " + std::to_string(chars) + " is not 4, 6, 8 or 10");
  }
  if (!std::isfinite(lat_deg) || lat_deg < -90.0 || lat_deg > 90.0) {
    return fail("latitude must be a finite number in [-90, 90] deg, got " + format_number(lat_deg));
  }
  if (!std::isfinite(lon_deg) || lon_deg < -180.0 || lon_deg > 180.0) {
    return fail("longitude must be a finite number in [-180, 180] deg, got " +
                format_number(lon_deg));
  }
  std::int64_t lon_units = grid_index(lon_deg + 180.0, kUnitsPerLonDeg);
  std::int64_t lat_units = grid_index(lat_deg + 90.0, kUnitsPerLatDeg);
  std::string out;
  for (std::size_t i = 0; i < static_cast<std::size_t>(chars) / 2; ++i) {
    const Level& level = kLevels[i];
    // Fields upper case (level 0 uses 'A'); every later letter pair lower case.
    out += static_cast<char>(level.first + lon_units / level.units);
    out += static_cast<char>(level.first + lat_units / level.units);
    lon_units %= level.units;
    lat_units %= level.units;
  }
  return out;
}

}  // namespace azt::astro
