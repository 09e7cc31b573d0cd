#include "common/horizon_mask_option.hpp"

#include "common/usage_error.hpp"

namespace azt::app {

orbit::HorizonMask parse_horizon_mask(const std::string& option, const std::string& text) {
  auto mask = orbit::HorizonMask::parse(text);
  if (!mask) throw UsageError(option + ": " + mask.error().message);
  return std::move(mask).value();
}

}  // namespace azt::app
