#pragma once
// How long each point of a scan or a noise measurement settles and dwells, read from a request
// body (`settle_s`, `dwell_s`; docs/web-api.md): the same fields and limits for POST /api/scan,
// /api/noise and the calibration session.

#include <nlohmann/json.hpp>

#include "azt/calibration/scan_session.hpp"

namespace azt::app {

/// The body's `settle_s` (0 to 60) and `dwell_s` (above 0, at most 60), each defaulting to
/// ScanTiming's; an ApiError (400) naming the field otherwise.
calibration::ScanTiming scan_timing_from(const nlohmann::json& body);

}  // namespace azt::app
