// The horizon mask as typed on the command line or in [satellites] mask (kept apart from the
// satellite catalogue so the configuration reader does not need the element-set parsers).
#include <sstream>

#include "azt/util/parse_number.hpp"
#include "cli_error.hpp"
#include "satellites.hpp"

namespace azt::app {

orbit::HorizonMask parse_horizon_mask(const std::string& option, const std::string& text) {
  std::vector<std::pair<double, double>> sectors;
  if (text.find(':') == std::string::npos) {
    const auto v = parse_finite_double(text);
    if (!v) throw UsageError(option + ": '" + text + "' is not a number of degrees");
    sectors.emplace_back(0.0, *v);
  } else {
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
      const auto colon = item.find(':');
      const auto az = parse_finite_double(item.substr(0, colon));
      const auto el =
          colon == std::string::npos ? std::nullopt : parse_finite_double(item.substr(colon + 1));
      if (!az || !el) {
        std::string why = option;
        why += ": '";
        why += item;
        why += "' is not AZ:MIN_EL (e.g. 0:5,90:10)";
        throw UsageError(why);
      }
      sectors.emplace_back(*az, *el);
    }
  }
  auto mask = orbit::HorizonMask::make(std::move(sectors));
  if (!mask) throw UsageError(option + ": " + mask.error().message);
  return mask.value();
}

}  // namespace azt::app
