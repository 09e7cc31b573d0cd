#pragma once
// GET /api/locator: a Maidenhead locator's square, or the locator of a position, by the core's
// maidenhead.hpp, so the console shows the other representation of what the operator types
// without a second implementation in the browser.

#include <string>

#include <nlohmann/json.hpp>

namespace azt::app {

/// `grid=FN06HE` → {"grid", "lat_deg", "lon_deg"} (the square's centre); `lat=46.2&lon=-79.4` →
/// the same with the 6-character locator. Throws ApiError(400) naming the query key.
nlohmann::json locator_json(const std::string& query);

}  // namespace azt::app
