#pragma once

#include "azt/calibration/pointing_model.hpp"

namespace azt::app {

class ConfigFile;
class ConfigSection;

/// The terms of a pointing model from a table holding ia_deg, ie_deg, ca_deg, npae_deg, an_deg,
/// aw_deg and sag_deg (each optional, default 0, within ±10°). Throws UsageError naming the key.
calibration::PointingTerms pointing_terms_from(const ConfigSection& s);

/// [pointing]: the station's fitted pointing model (docs/calibration.md), applied
/// to every reading after the encoder offset.
calibration::PointingTerms station_pointing_from(const ConfigFile& file);

/// [sim.mount_errors]: how the simulated mount really points: az_offset_deg, el_offset_deg,
/// collimation_deg, nonperp_deg, az_tilt_deg towards az_tilt_toward_deg, el_sag_deg (each ±10°;
/// the tilt's direction any azimuth). `sim` is the [sim] table.
calibration::PointingTerms mount_errors_from(const ConfigSection& sim);

}  // namespace azt::app
