#include <string>

#include "azt/orbit/passes.hpp"
#include "azt/util/parse_number.hpp"

namespace azt::orbit {
namespace {

/// "AZ:MIN_EL" -> the pair; nullopt when either number is missing or not finite.
std::optional<std::pair<double, double>> sector(std::string_view item) {
  const auto colon = item.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const auto az = parse_finite_double(item.substr(0, colon));
  const auto el = parse_finite_double(item.substr(colon + 1));
  if (!az || !el) return std::nullopt;
  return std::pair{*az, *el};
}

}  // namespace

Result<HorizonMask> HorizonMask::parse(std::string_view text) {
  std::vector<std::pair<double, double>> sectors;
  if (text.find(':') == std::string_view::npos) {
    const auto v = parse_finite_double(text);
    if (!v) return fail("'" + std::string(text) + "' is not a number of degrees");
    sectors.emplace_back(0.0, *v);
    return make(std::move(sectors));
  }
  while (!text.empty()) {
    const auto comma = text.find(',');
    const std::string_view item = text.substr(0, comma);
    const auto s = sector(item);
    if (!s) return fail("'" + std::string(item) + "' is not AZ:MIN_EL (e.g. 0:5,90:10)");
    sectors.push_back(*s);
    text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
  }
  return make(std::move(sectors));
}

}  // namespace azt::orbit
