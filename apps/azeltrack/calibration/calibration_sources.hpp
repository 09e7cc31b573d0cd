#pragma once
// Which sources a calibration session may scan (docs/calibration.md "Which sources a station
// hears"): each of the station's targets with a flux known at the band, its signal-to-noise at
// one scan point from [station] dish_m, efficiency and [receiver] tsys_k (core source_snr), and
// whether it is worth scanning. Without the dish every source is offered, saying why.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/astro/target.hpp"
#include "azt/calibration/noise_sources.hpp"
#include "config/receiver_config.hpp"

namespace azt::app {

/// The least SNR at a scan point worth scanning (docs/calibration.md: 10 dB).
inline constexpr double kWorthScanningSnrDb = 10.0;
/// The quiet Sun's F10.7 (a spotless day): the Sun's estimate errs low, never high.
inline constexpr double kQuietSunF107Sfu = 70.0;

struct SourceOffer {
  std::string name;
  std::optional<double> snr_db;  ///< none: not estimated (no dish, no flux at the band)
  bool worth = true;
  std::string why;
  double size_deg = 0.0;  ///< its Gaussian-equivalent width, for the planner
  bool sun = false;       ///< scanned every sun_every_min
};

/// The source's flux and size at `freq_mhz`: the quiet Sun, the Moon at 220 K, Cas A and Cyg A
/// from their fits, other catalogue sources at the catalogue's band nearest; none for the rest.
std::optional<calibration::SourceAtBand> target_at_band(const astro::Target& target,
                                                        double freq_mhz);

/// Each target's offer; `dwell_s` of readings per point, `beamwidth_deg` the scan's beam.
std::vector<SourceOffer> offer_sources(const std::vector<astro::Target>& targets,
                                       const DishConfig& dish, std::optional<double> freq_mhz,
                                       double beamwidth_deg, double dwell_s);

/// GET /api/calibration/sources: {"sources": [{"name", "snr_db", "worth", "why"}], "given"}.
nlohmann::json offers_json(const std::vector<SourceOffer>& offers, bool given);

}  // namespace azt::app
