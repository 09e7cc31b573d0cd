#include "console/scan_timing_body.hpp"

#include "console/body_fields.hpp"
#include "console/console_model.hpp"

namespace azt::app {

calibration::ScanTiming scan_timing_from(const nlohmann::json& body) {
  calibration::ScanTiming timing;
  timing.settle_s = body_optional_number(body, "settle_s").value_or(timing.settle_s);
  timing.dwell_s = body_optional_number(body, "dwell_s").value_or(timing.dwell_s);
  if (!(timing.settle_s >= 0.0 && timing.settle_s <= 60.0)) {
    throw ApiError(400, "settle_s", "settle_s must be 0 to 60");
  }
  if (!(timing.dwell_s > 0.0 && timing.dwell_s <= 60.0)) {
    throw ApiError(400, "dwell_s", "dwell_s must be above 0 and at most 60");
  }
  return timing;
}

}  // namespace azt::app
