#include "calibration/calibration_sources.hpp"

#include <cmath>
#include <cstdio>

#include "azt/calibration/noise_expectation.hpp"
#include "azt/calibration/source_snr.hpp"

namespace azt::app {
namespace {

/// The catalogue's flux at the band it lists nearest to `freq_mhz` (in frequency ratio).
std::optional<double> catalogue_flux_jy(const astro::RadioSource& s, double freq_mhz) {
  const std::optional<double> fluxes[] = {s.flux_1296_jy, s.flux_2304_jy, s.flux_10368_jy};
  const double bands[] = {1296.0, 2304.0, 10368.0};
  std::optional<double> best;
  double best_ratio = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double ratio = std::fabs(std::log(freq_mhz / bands[i]));
    if (fluxes[i] && (!best || ratio < best_ratio)) {
      best = fluxes[i];
      best_ratio = ratio;
    }
  }
  return best;
}

std::string snr_text(double snr_db) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", snr_db);
  return text;
}

SourceOffer estimate(const astro::Target& t, const calibration::SourceAtBand& at,
                     const DishConfig& dish, double beamwidth_deg, double dwell_s) {
  const double size = calibration::equivalent_gaussian_width_deg(at.shape, at.size_deg);
  const calibration::DishSetup setup{*dish.dish_m, *dish.efficiency, *dish.tsys_k, beamwidth_deg};
  calibration::PointNoise noise;
  if (dish.bandwidth_hz) {
    noise.reading_noise_db =
        calibration::radiometer_noise_db(*dish.bandwidth_hz, dish.integration_s);
  }
  noise.readings = std::max(1.0, dwell_s / dish.integration_s);
  const auto e = calibration::estimate_source({t.name, at.flux_jy, size}, setup, noise);
  SourceOffer o{t.name, e.snr_db, e.snr_db >= kWorthScanningSnrDb,
                "",     size,     t.kind == astro::Target::Kind::Sun};
  o.why = o.worth ? "SNR " + snr_text(e.snr_db) + " dB at a scan point"
                  : "SNR " + snr_text(e.snr_db) + " dB at a scan point, below " +
                        snr_text(kWorthScanningSnrDb) + " dB: too faint to scan";
  return o;
}

}  // namespace

std::optional<calibration::SourceAtBand> target_at_band(const astro::Target& target,
                                                        double freq_mhz) {
  switch (target.kind) {
    case astro::Target::Kind::Sun:
      return calibration::sun_at_band(
          calibration::solar_flux_at_band_sfu(kQuietSunF107Sfu, freq_mhz), freq_mhz);
    case astro::Target::Kind::Moon:
      return calibration::moon_at_band(220.0, 0.52, freq_mhz);
    case astro::Target::Kind::Source: {
      if (target.source == nullptr) return std::nullopt;
      if (const auto star = calibration::parse_noise_source(target.source->key)) {
        if (auto fit = calibration::radio_star_at_band(*star, freq_mhz)) return fit;
      }
      const auto flux = catalogue_flux_jy(*target.source, freq_mhz);
      if (!flux) return std::nullopt;
      return calibration::SourceAtBand{*flux, calibration::SourceShape::Point, 0.0};
    }
    case astro::Target::Kind::RaDec:
    case astro::Target::Kind::Spacecraft:
      return std::nullopt;
  }
  return std::nullopt;
}

std::vector<SourceOffer> offer_sources(const std::vector<astro::Target>& targets,
                                       const DishConfig& dish, std::optional<double> freq_mhz,
                                       double beamwidth_deg, double dwell_s) {
  std::vector<SourceOffer> out;
  for (const astro::Target& t : targets) {
    const bool sun = t.kind == astro::Target::Kind::Sun;
    calibration::SourceAtBand at{};  // not an optional: GCC 12 warns of its payload
    bool known = false;
    if (freq_mhz) {
      if (const auto found = target_at_band(t, *freq_mhz)) {
        at = *found;
        known = true;
      }
    }
    const double size = calibration::equivalent_gaussian_width_deg(at.shape, at.size_deg);
    if (!dish.given()) {
      out.push_back({t.name, std::nullopt, true,
                     "not estimated: [station] dish_m, efficiency and [receiver] tsys_k are not "
                     "all given",
                     size, sun});
    } else if (!known) {
      out.push_back({t.name, std::nullopt, false, "no flux known at the band", 0.0, sun});
    } else {
      out.push_back(estimate(t, at, dish, beamwidth_deg, dwell_s));
    }
  }
  return out;
}

nlohmann::json offers_json(const std::vector<SourceOffer>& offers, bool given) {
  nlohmann::json list = nlohmann::json::array();
  for (const SourceOffer& o : offers) {
    list.push_back({{"name", o.name},
                    {"snr_db", o.snr_db ? nlohmann::json(*o.snr_db) : nlohmann::json(nullptr)},
                    {"worth", o.worth},
                    {"why", o.why}});
  }
  return {{"sources", list}, {"given", given}};
}

}  // namespace azt::app
