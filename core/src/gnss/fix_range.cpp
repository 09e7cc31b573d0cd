#include "azt/gnss/fix_range.hpp"

#include <cmath>

#include "azt/util/format_number.hpp"

namespace azt::gnss {
namespace {

std::optional<std::string> outside(const char* what, double value, double low, double high) {
  if (std::isfinite(value) && value >= low && value <= high) return std::nullopt;
  return std::string(what) + " " + format_number(value) + " is outside [" + format_number(low) +
         ", " + format_number(high) + "]";
}

}  // namespace

std::optional<std::string> out_of_range(const GpsFix& fix) {
  if (fix.mode == FixMode::None) return std::nullopt;
  if (auto why = outside("latitude", fix.lat_deg, -90.0, 90.0)) return why;
  if (auto why = outside("longitude", fix.lon_deg, -180.0, 180.0)) return why;
  if (fix.alt_m) return outside("altitude", *fix.alt_m, kLowestStationAltM, kHighestStationAltM);
  return std::nullopt;
}

}  // namespace azt::gnss
