#include "console/locator_api.hpp"

#include <cmath>
#include <limits>

#include "azt/astro/maidenhead.hpp"
#include "console/console_model.hpp"
#include "console/query_string.hpp"

namespace azt::app {
namespace {

double number(const std::string& query, const std::string& key) {
  const auto text = query_value(query, key);
  if (!text) throw ApiError(400, key, "give grid=LOCATOR, or lat= and lon=");
  std::size_t used = 0;
  double v = std::numeric_limits<double>::quiet_NaN();
  try {
    v = std::stod(*text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text->size() || !std::isfinite(v)) {
    throw ApiError(400, key, key + " must be a number");
  }
  return v;
}

}  // namespace

nlohmann::json locator_json(const std::string& query) {
  if (const auto grid = query_value(query, "grid")) {
    const auto square = astro::decode_locator(*grid);
    if (!square) throw ApiError(400, "grid", square.error().message);
    return {{"grid", *grid}, {"lat_deg", square->lat_deg}, {"lon_deg", square->lon_deg}};
  }
  const double lat = number(query, "lat");
  const double lon = number(query, "lon");
  const auto grid = astro::encode_locator(lat, lon, 6);
  if (!grid) throw ApiError(400, "lat", grid.error().message);
  return {{"grid", *grid}, {"lat_deg", lat}, {"lon_deg", lon}};
}

}  // namespace azt::app
