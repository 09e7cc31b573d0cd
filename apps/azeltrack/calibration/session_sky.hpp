#pragma once
// The sky of a calibration session in the daemon: the requested sources found among the
// station's targets, each with its SNR estimate (calibration_sources.hpp) and the Sun marked
// periodic, their positions from the sky engine (one SkyFollower each, interpolated between
// whole seconds) and the site's limits from the station's travel.

#include "azt/astro/ephemeris.hpp"
#include "azt/control/station_setup.hpp"
#include "calibration/calibration_request.hpp"
#include "calibration/calibration_runner.hpp"
#include "config/receiver_config.hpp"
#include "config/sky_config.hpp"

namespace azt::app {

/// The session's sky, or the refusal naming `sources` (an unknown name, a source with no flux at
/// the band, one too faint to scan).
Result<SessionSky> session_sky(const CalibrationRequest& request, const astro::Ephemeris& ephemeris,
                               const SkyConfig& sky, const DishConfig& dish,
                               const control::StationSetup& station);

}  // namespace azt::app
