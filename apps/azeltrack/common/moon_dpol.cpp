#include "common/moon_dpol.hpp"

#include "azt/astro/sky.hpp"
#include "azt/eme/polarisation.hpp"

namespace azt::app {

std::optional<double> moon_dpol_deg(const astro::Ephemeris& ephemeris, const SkySettings& settings,
                                    double unix_s) {
  if (!settings.dx) return std::nullopt;
  const auto time = time_scales_for(astro::UtcInstant::from_unix_seconds(unix_s), settings.dut1_s);
  if (!time) return std::nullopt;
  const auto epoch = astro::make_epoch(ephemeris, *time);
  if (!epoch) return std::nullopt;
  const auto own =
      astro::observe_moon(ephemeris, *epoch, astro::make_station(*epoch, settings.observer));
  const auto dx = astro::observe_moon(ephemeris, *epoch, astro::make_station(*epoch, *settings.dx));
  if (!own || !dx) return std::nullopt;
  // The airless elevation, as WSJT-X's and as moon_conditions takes it for the EME data.
  return eme::dpol_deg(
      eme::parallactic_angle_deg(settings.observer.lat_deg, own->az_deg, own->el_geometric_deg),
      eme::parallactic_angle_deg(settings.dx->lat_deg, dx->az_deg, dx->el_geometric_deg));
}

}  // namespace azt::app
