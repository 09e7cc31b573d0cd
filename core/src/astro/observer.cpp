#include "azt/astro/observer.hpp"
#include "azt/util/format_number.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>

namespace azt::astro {

namespace {

constexpr double kMinHeightM = -500.0;   ///< below the Dead Sea shore (−430 m)
constexpr double kMaxHeightM = 10000.0;  ///< above Everest; higher is an aircraft, not a station

/// Error when `value` is not finite or lies outside [lo, hi].
std::optional<Error> check_range(const char* field, double value, double lo, double hi,
                                 const char* unit) {
  if (std::isfinite(value) && value >= lo && value <= hi) return std::nullopt;
  return fail(std::string(field) + " must be a finite number in [" + format_number(lo) + ", " +
              format_number(hi) + "] " + unit + ", got " + format_number(value));
}

}  // namespace

Result<Observer> Observer::make(double lat_deg, double lon_deg, double height_m) {
  if (auto e = check_range("latitude", lat_deg, -90.0, 90.0, "deg")) return *e;
  if (auto e = check_range("longitude", lon_deg, -180.0, 180.0, "deg")) return *e;
  if (auto e = check_range("height", height_m, kMinHeightM, kMaxHeightM, "m")) return *e;
  return Observer{lat_deg, lon_deg, height_m};
}

}  // namespace azt::astro
