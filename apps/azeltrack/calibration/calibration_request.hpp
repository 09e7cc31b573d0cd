#pragma once
// What an operator asks of a calibration session (POST /api/calibration/session,
// docs/web-api.md): the sources, how long, the kind of scan and its beam, the Sun's interval.
// Kept as JSON beside the configuration while the session runs, so that a restart resumes it.

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/calibration/calibration_session.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

struct CalibrationRequest {
  std::vector<std::string> sources;  ///< names as the station knows them ("sun", "casa", …)
  double hours = 2.0;
  calibration::ScanSpec spec;  ///< kind, beamwidth, points per line, span
  calibration::ScanTiming timing;
  double sun_every_min = 30.0;  ///< the Sun's interval (0: by coverage, as the rest)
  bool refine = true;           ///< scan again centred on what the first scan found
  std::size_t max_scans = 60;   ///< sources found; then the session is done

  /// The request as the API's body and the session file hold it.
  [[nodiscard]] nlohmann::json to_json() const;
};

/// Reads a request; every refusal begins with the field at fault ("hours: must be …").
Result<CalibrationRequest> calibration_request_from(const nlohmann::json& body);

}  // namespace azt::app
