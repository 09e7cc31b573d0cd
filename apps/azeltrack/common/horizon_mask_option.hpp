#pragma once
// The horizon mask as typed on the command line or in [satellites] mask (kept apart from the
// satellite catalogue so the configuration reader does not need the element-set parsers).

#include <string>

#include "azt/orbit/passes.hpp"

namespace azt::app {

/// "5" (a flat horizon) or "AZ:MIN_EL,…" sectors ("0:5,90:12,200:3"); throws UsageError naming
/// `option` ("--mask", "[satellites] mask").
orbit::HorizonMask parse_horizon_mask(const std::string& option, const std::string& text);

}  // namespace azt::app
