#pragma once
// Pointing calibration in simulation (docs/calibration.md): the daemon's station on the simulated
// plants, whose beam points wrong the way a real mount's does ([sim.mount_errors]: PlantSetup's
// pointing_errors), runs the daemon's calibration session (calibration/calibration_session.hpp:
// its planner picks the Sun, the Moon and the radio sources across the sky, each scan runs as a
// ScanSession, each source found becomes rows of the scan log) with the simulated receiver, fits
// the pointing model to the log and measures the beam's error over the sky before and after.
// Each scan point is measured after the antenna settles, with the ephemeris read again at every
// tick (the source moves during a scan).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "azt/astro/time_scales.hpp"
#include "azt/calibration/beam_error.hpp"
#include "azt/calibration/pointing_fit.hpp"
#include "azt/calibration/scan_fit.hpp"
#include "azt/calibration/scan_log.hpp"
#include "azt/sim/radio_receiver.hpp"
#include "azt/sim/station_sim.hpp"

namespace azt::sim {

/// A source the scenario may scan, and what the receiver sees of it.
struct CalibrationSource {
  std::string name;
  SkyTrack track;       ///< its apparent position at t seconds after the start
  double peak_k = 0.0;  ///< antenna temperature with the beam on it
  double size_deg = 0.0;
};

struct CalibrationSimSetup {
  StationSimSetup station;  ///< station.plant.pointing_errors: the mount's real errors
  ReceiverSetup receiver;
  std::vector<CalibrationSource> sources;
  astro::UtcInstant epoch;      ///< the UTC of t = 0 (the scan log's times)
  double duration_s = 86400.0;  ///< the longest the scenario runs, simulated
  std::size_t max_scans = 60;   ///< sources found; then the session is done
  double min_el_deg = 10.0;     ///< refraction's error grows below (astronomy-and-eme.md §8)
  double max_el_deg = 80.0;     ///< azimuth gets fast and ill-conditioned above
  double min_snr_db = 15.0;     ///< sources fainter than this at a scan point are not scanned
  double sun_every_s = 0.0;     ///< the Sun every this long while it is up (0: by coverage)
  std::size_t points_per_line = 21;
  double half_span_beams = 2.0;
  double settle_s = 1.0;  ///< after the axes stop, before reading
  double dwell_s = 4.0;   ///< readings averaged per point
};

/// One source's scan: what the controller believed, and what the fit found.
struct ScanRecord {
  std::string source;
  double t_s = 0.0;       ///< when the final scan ended
  control::AzEl sky;      ///< the source when the final scan's elevation line was measured
  control::AzEl sky_xel;  ///< and when its cross-elevation line was
  std::optional<calibration::ScanFit> fit;  ///< of the final (refining) cross scan
  std::string refused;                      ///< why no fit, when none
  std::size_t scans = 0;                    ///< scans run for this source (search and refine)
};

struct CalibrationSimResult {
  std::vector<ScanRecord> scans;
  std::vector<calibration::ScanLogEntry> log;  ///< the session's scan log
  std::optional<calibration::PointingFit> fit;
  std::string fit_refused;
  calibration::BeamError before;  ///< the beam's error over the sky with the station's model
  calibration::BeamError after;   ///< and with the fitted one
  /// The beam's true error with the encoders in the loop (beam_error_with_encoders), and the
  /// least any model could leave with them.
  calibration::BeamError after_with_encoders;
  double quantisation_floor_deg = 0.0;
  std::vector<std::string> faults;
  double simulated_s = 0.0;
};

CalibrationSimResult simulate_calibration(const CalibrationSimSetup& setup);

/// One source's scans (a cross scan, a raster if it finds nothing, a cross scan centred on what
/// was found) on a fresh station at t = 0, whatever the planner would say: the offset a single
/// scan finds, e.g. of the Sun.
ScanRecord simulate_single_scan(const CalibrationSimSetup& setup, const CalibrationSource& source);

}  // namespace azt::sim
