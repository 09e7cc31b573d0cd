#include "common/sky_report.hpp"

#include "azt/astro/bands.hpp"
#include "azt/eme/moon_conditions.hpp"
#include "azt/eme/sky_temperature.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json moon_echo_json(const astro::TargetReport& r, const SkySettings& settings) {
  nlohmann::json out;
  const double rate = *r.observation.place.range_rate_km_s;
  out["echo_delay_s"] = astro::echo_delay_s(*r.observation.place.distance_km);
  if (settings.freq_mhz) {
    out["freq_mhz"] = *settings.freq_mhz;
    out["echo_doppler_hz"] = astro::self_echo_doppler_hz(*settings.freq_mhz, rate);
    if (r.dx_range_rate_km_s) {
      out["dx_echo_doppler_hz"] =
          astro::dx_echo_doppler_hz(*settings.freq_mhz, rate, *r.dx_range_rate_km_s);
    }
  }
  nlohmann::json bands = nlohmann::json::array();
  for (const auto& band : astro::eme_bands()) {
    nlohmann::json b{{"band", band.name},
                     {"freq_mhz", band.freq_mhz},
                     {"echo_doppler_hz", astro::self_echo_doppler_hz(band.freq_mhz, rate)}};
    if (r.dx_range_rate_km_s) {
      b["dx_echo_doppler_hz"] =
          astro::dx_echo_doppler_hz(band.freq_mhz, rate, *r.dx_range_rate_km_s);
    }
    bands.push_back(b);
  }
  out["bands"] = bands;
  return out;
}

/// The echo Doppler's change over the next minute, Hz per minute (WSJT-X's Df/dt in the Astro
/// window and azel.dat, lib/astro0.f90): self, and DX when there is one.
void doppler_rates_json(const astro::TargetReport& r, const astro::SkySnapshot& snapshot,
                        double freq_mhz, nlohmann::json& out) {
  const auto later = snapshot.later(60.0);
  if (!later) return;
  const auto moon_later = later->observe(astro::Target::moon());
  if (!moon_later || !moon_later->observation.place.range_rate_km_s) return;
  const double rate = *r.observation.place.range_rate_km_s;
  const double rate_later = *moon_later->observation.place.range_rate_km_s;
  out["echo_doppler_rate_hz_min"] = astro::self_echo_doppler_hz(freq_mhz, rate_later) -
                                    astro::self_echo_doppler_hz(freq_mhz, rate);
  if (r.dx_range_rate_km_s && moon_later->dx_range_rate_km_s) {
    out["dx_echo_doppler_rate_hz_min"] =
        astro::dx_echo_doppler_hz(freq_mhz, rate_later, *moon_later->dx_range_rate_km_s) -
        astro::dx_echo_doppler_hz(freq_mhz, rate, *r.dx_range_rate_km_s);
  }
}

}  // namespace

std::optional<eme::MoonConditions> moon_conditions_at(const astro::TargetReport& r,
                                                      const astro::SkySnapshot& snapshot,
                                                      const SkySettings& settings) {
  const auto sun = snapshot.observe(astro::Target::sun());
  if (!sun) return std::nullopt;
  eme::MoonInputs in;
  in.lat_deg = settings.observer.lat_deg;
  in.moon = r.observation.place;
  in.sun = sun->observation.place;
  in.dx_moon = r.dx_place;
  in.freq_mhz = settings.freq_mhz.value_or(144.0);
  if (settings.dx && r.dx_place) in.dx_lat_deg = settings.dx->lat_deg;
  in.tt_jd = snapshot.time().tt.total();
  if (const auto later = snapshot.later(60.0)) {  // the libration's change in a minute
    if (const auto moon_later = later->observe(astro::Target::moon())) {
      in.moon_minute_later = moon_later->observation.place;
      in.dx_moon_minute_later = moon_later->dx_place;
    }
  }
  return eme::moon_conditions(in);
}

namespace {

/// Dpol, MNR, Tsky, Dgrd, the Sun's separation and the lit fraction (WSJT-X's definitions,
/// docs/eme.md). Tsky and Dgrd at the station's frequency, and per band. `dpol_deg` is WSJT-X's
/// Dpol (between the two stations, null without a DX); `dx_dpol_deg` is its former name, kept
/// for one version.
nlohmann::json moon_eme_json(const astro::TargetReport& r, const astro::SkySnapshot& snapshot,
                             const SkySettings& settings, nlohmann::json& bands) {
  const auto conditions = moon_conditions_at(r, snapshot, settings);
  if (!conditions) return nlohmann::json::object();
  const eme::MoonConditions& c = *conditions;
  const double freq_mhz = settings.freq_mhz.value_or(144.0);
  nlohmann::json out{{"parallactic_deg", c.parallactic_deg},
                     {"dpol_deg", optional_json(c.dx_dpol_deg)},
                     {"self_dpol_deg", c.dpol_deg},
                     {"dx_dpol_deg", optional_json(c.dx_dpol_deg)},
                     {"mnr_db", optional_json(c.mnr_db)},
                     {"ecliptic_lon_deg", c.ecliptic_lon_deg},
                     {"sun_sep_deg", c.sun_sep_deg},
                     {"illumination", c.illumination},
                     {"width_hz", nullptr},
                     {"dx_width_hz", nullptr},
                     {"tsky_k", nullptr},
                     {"dgrd_db", nullptr}};
  if (settings.freq_mhz) {
    out["tsky_k"] = c.tsky_k;
    out["dgrd_db"] = c.dgrd_db;
    out["width_hz"] = optional_json(c.width_hz);
    out["dx_width_hz"] = optional_json(c.dx_width_hz);
  }
  const double km = r.observation.place.distance_km.value_or(eme::kPerigeeKm);
  for (auto& b : bands) {
    const double tsky = eme::tsky_k(c.ecliptic_lon_deg, b["freq_mhz"].get<double>());
    b["tsky_k"] = tsky;
    b["dgrd_db"] = eme::dgrd_db(tsky, b["freq_mhz"].get<double>(), km);
    if (c.width_hz) b["width_hz"] = *c.width_hz * b["freq_mhz"].get<double>() / freq_mhz;
  }
  return out;
}

}  // namespace

astro::SkySite sky_site(const SkySettings& settings) {
  return astro::SkySite{settings.observer, settings.dx, settings.atmosphere};
}

Result<astro::SkySnapshot> sky_snapshot(const astro::Ephemeris& ephemeris,
                                        const SkySettings& settings, const astro::UtcInstant& utc) {
  auto time = time_scales_for(utc, settings.dut1_s);
  if (!time) return time.error();
  return astro::SkySnapshot::at(ephemeris, sky_site(settings), *time);
}

astro::SkySnapshot sky_snapshot_or_throw(const astro::Ephemeris& ephemeris,
                                         const SkySettings& settings,
                                         const astro::UtcInstant& utc) {
  auto snapshot = sky_snapshot(ephemeris, settings, utc);
  if (!snapshot) throw UsageError(snapshot.error().message);
  return std::move(snapshot).value();
}

astro::TargetReport observe_or_throw(const astro::SkySnapshot& snapshot,
                                     const astro::Target& target) {
  auto report = snapshot.observe(target);
  if (!report) throw UsageError(report.error().message);
  return std::move(report).value();
}

nlohmann::json report_json(const astro::TargetReport& r, const astro::SkySnapshot& snapshot,
                           const SkySettings& settings, const std::string& ephemeris_name) {
  const astro::Place& p = r.observation.place;
  const astro::TimeScales& t = snapshot.time();
  nlohmann::json out{
      {"target", r.target.name},
      {"utc", astro::format_iso8601_utc(t.utc)},
      {"ephemeris", ephemeris_name},
      {"observer",
       {{"lat_deg", settings.observer.lat_deg},
        {"lon_deg", settings.observer.lon_deg},
        {"height_m", settings.observer.height_m},
        {"grid", settings.grid}}},
      {"dut1_s", t.dut1_s},
      {"tai_minus_utc_s", t.tai_minus_utc_s},
      {"refraction", std::string(astro::to_string(settings.atmosphere.model))},
      {"az_deg", p.az_deg},
      {"el_deg", r.observation.el_deg},
      {"el_geometric_deg", p.el_geometric_deg},
      {"ra_deg", p.ra_deg},
      {"dec_deg", p.dec_deg},
      {"distance_km", optional_json(p.distance_km)},
      {"range_rate_km_s", optional_json(p.range_rate_km_s)},
  };
  if (r.target.kind == astro::Target::Kind::Moon) {
    out.update(moon_echo_json(r, settings));
    out.update(moon_eme_json(r, snapshot, settings, out["bands"]));
    if (settings.freq_mhz) doppler_rates_json(r, snapshot, *settings.freq_mhz, out);
  }
  if (r.dx_place) {
    out["dx"] = {{"grid", settings.dx_grid},
                 {"az_deg", r.dx_place->az_deg},
                 {"el_geometric_deg", r.dx_place->el_geometric_deg},
                 {"dec_deg", r.dx_place->dec_deg},
                 {"range_rate_km_s", optional_json(r.dx_range_rate_km_s)}};
  }
  return out;
}

}  // namespace azt::app
