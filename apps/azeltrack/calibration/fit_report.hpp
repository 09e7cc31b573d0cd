#pragma once
// The pointing model's fit as the program prints it (docs/calibration.md): `azeltrack pointing fit
// --json`, `azeltrack simulate --scenario calibrate` and the console read the same JSON.

#include <vector>

#include <nlohmann/json.hpp>

#include "azt/calibration/pointing_fit.hpp"
#include "azt/calibration/scan_log.hpp"

namespace azt::app {

/// {"ia_deg": …, "ie_deg": …, …} in [pointing]'s key names.
nlohmann::json terms_json(const calibration::PointingTerms& terms);

/// {"terms", "std_errors", "rms_before_deg", "rms_after_deg", "max_after_deg", "scans", "held"
/// (each held term's key: why), "residuals"}: one residual per log row, beside the row's time,
/// source and place, before and after (beam minus source on the sky, degrees), and whether it
/// counted.
nlohmann::json fit_json(const calibration::PointingFit& fit,
                        const std::vector<calibration::ScanLogEntry>& rows);

}  // namespace azt::app
