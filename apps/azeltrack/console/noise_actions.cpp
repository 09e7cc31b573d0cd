// POST /api/noise and /api/noise/stop (docs/web-api.md): a noise measurement of the Sun, the Moon
// or a radio source through the station's front door, as a pointing scan is started
// (daemon_console.cpp act_scan): the settings checked before anything moves, then the source
// tracked, then the measurement run by station/noise_runner on the control tick.
#include <string>

#include "azt/calibration/noise_expectation.hpp"
#include "azt/calibration/noise_sources.hpp"
#include "console/body_fields.hpp"
#include "console/daemon_console.hpp"
#include "console/scan_timing_body.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

/// The plan and timing from the request; refusals name the field.
std::pair<calibration::NoisePlan, calibration::ScanTiming> noise_settings(const json& body) {
  calibration::NoisePlan plan;
  plan.beamwidth_deg = body_number(body, "beamwidth_deg");
  plan.offset_beams = body_optional_number(body, "offset_beams").value_or(plan.offset_beams);
  if (body.contains("repeats")) {
    plan.repeats = static_cast<std::size_t>(
        body_whole_number(body, "repeats", 2, 50, "repeats must be a whole number 2 to 50"));
  }
  const calibration::ScanTiming timing = scan_timing_from(body);
  // The plan's own refusals name their field first ("beamwidth_deg: must be …").
  if (auto ok = calibration::NoiseMeasurement::start(plan, timing, 0.0); !ok) {
    const std::string& why = ok.error().message;
    throw ApiError(400, why.substr(0, why.find(':')), why);
  }
  return {plan, timing};
}

/// The source at the band from the request: the Sun's flux (band_flux_sfu, or solar_flux_sfu
/// the 10.7 cm index, scaled), the Moon's brightness and size, Cas A and Cyg A from their fits.
calibration::SourceAtBand source_at_band(const json& body, calibration::NoiseSource source,
                                         double freq_mhz) {
  switch (source) {
    case calibration::NoiseSource::Sun: {
      if (const auto band = body_optional_number(body, "band_flux_sfu")) {
        return calibration::sun_at_band(*band, freq_mhz);
      }
      const double f107 = body_number(body, "solar_flux_sfu");
      return calibration::sun_at_band(calibration::solar_flux_at_band_sfu(f107, freq_mhz),
                                      freq_mhz);
    }
    case calibration::NoiseSource::Moon:
      return calibration::moon_at_band(body_optional_number(body, "moon_k").value_or(220.0),
                                       body_optional_number(body, "moon_deg").value_or(0.52),
                                       freq_mhz);
    case calibration::NoiseSource::CasA:
    case calibration::NoiseSource::CygA:
      return *calibration::radio_star_at_band(source, freq_mhz);
  }
  throw ApiError(400, "source", "unknown source");
}

/// What to expect, when the request gives the station (dish_m, efficiency, tsys_k) and the
/// source is one whose flux is known; checked before anything moves.
std::optional<NoiseExpected> expected_from(const json& body, const std::string& name,
                                           const SkySettings& sky, double beamwidth_deg) {
  if (!body.contains("dish_m") && !body.contains("efficiency") && !body.contains("tsys_k")) {
    return std::nullopt;
  }
  const auto source = calibration::parse_noise_source(name);
  if (!source) throw ApiError(400, "source", "an expected value needs sun, moon, casa or cyga");
  const auto freq = body_optional_number(body, "freq_mhz");
  if (!freq && !sky.freq_mhz) throw ApiError(400, "freq_mhz", "freq_mhz is required (no band set)");
  NoiseExpected e;
  e.station = {freq.value_or(sky.freq_mhz.value_or(0.0)), body_number(body, "dish_m"),
               body_number(body, "efficiency"), body_number(body, "tsys_k"), beamwidth_deg};
  e.source = source_at_band(body, *source, e.station.freq_mhz);
  if (auto ok = calibration::expected_noise(e.station, e.source); !ok) {
    const std::string& why = ok.error().message;
    throw ApiError(400, why.substr(0, why.find(':')), why);
  }
  return e;
}

}  // namespace

json DaemonConsole::act_noise(const std::string& action, const json& body,
                              const std::string& source) {
  if (action == "noise/stop") {
    if (p_.noise != nullptr) p_.noise->stop("stopped by " + source);
    return p_.noise != nullptr ? p_.noise->to_json() : json{{"state", "idle"}};
  }
  if (p_.noise == nullptr) throw ApiError(503, "", "no noise measurements here");
  const auto [plan, timing] = noise_settings(body);
  const std::string name = body_text(body, "source");
  const auto expected = expected_from(body, name, p_.config.sky.settings, plan.beamwidth_deg);
  if (auto ready = p_.noise->ready(p_.monotonic_s()); !ready) {
    throw ApiError(503, "", ready.error().message);
  }
  if (p_.scanner != nullptr && p_.scanner->running()) {
    throw ApiError(409, "", "a pointing scan is running: stop it first");
  }
  if (p_.calibration != nullptr && p_.calibration->running()) {
    throw ApiError(409, "", "a calibration session is running: stop it first");
  }
  json pointed = act_target(json{{"name", name}}, source);  // tracks the source, or refuses
  if (!p_.sky.target()) throw ApiError(400, "source", "a noise measurement needs a sky source");
  auto started = p_.noise->start(p_.sky.target()->name, plan, timing, expected, p_.monotonic_s());
  if (!started) throw ApiError(503, "", started.error().message);
  p_.log(source + ": noise measurement of " + p_.sky.target()->name);
  pointed["noise"] = p_.noise->to_json();
  return pointed;
}

}  // namespace azt::app
