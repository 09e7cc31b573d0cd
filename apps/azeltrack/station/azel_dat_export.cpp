#include "station/azel_dat_export.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <utility>

#include "azt/astro/sky.hpp"
#include "azt/eme/azel_dat.hpp"
#include "common/sky_report.hpp"

namespace azt::app {
namespace {

constexpr double kSecondsPerDay = 86400.0;

}  // namespace

AzelDatExport::AzelDatExport(boost::asio::io_context& io, AzelDatParts parts)
    : p_(std::move(parts)), timer_(io) {
  write_now();
  arm();
}

void AzelDatExport::arm() {
  timer_.expires_after(std::chrono::seconds(1));
  timer_.async_wait([this](const boost::system::error_code& ec) {
    if (ec) return;
    write_now();
    arm();
  });
}

eme::AzelDat::PolLine AzelDatExport::pol_line(const astro::TargetReport& moon,
                                              const astro::SkySnapshot& sky) const {
  const auto c = moon_conditions_at(moon, sky, p_.sky.settings);
  if (!c) return {};
  // WSJT-X writes 0 for what needs a DX grid when there is none (lib/astrosub.f90).
  return {c->dx_dpol_deg.value_or(0.0), c->mnr_db.value_or(0.0), c->dgrd_db,
          c->width_hz.value_or(0.0), c->dx_width_hz.value_or(0.0)};
}

std::optional<std::string> AzelDatExport::text_at(double unix_s) {
  const auto sky =
      sky_snapshot(p_.ephemeris, p_.sky.settings, astro::UtcInstant::from_unix_seconds(unix_s));
  if (!sky) return std::nullopt;
  const auto moon = sky->observe(astro::Target::moon());
  const auto sun = sky->observe(astro::Target::sun());
  if (!moon || !sun) return std::nullopt;
  eme::AzelDat d;
  d.utc_s_of_day = std::fmod(std::floor(unix_s), kSecondsPerDay);
  d.moon_az_deg = moon->observation.place.az_deg;
  d.moon_el_deg = moon->observation.el_deg;
  d.sun_az_deg = sun->observation.place.az_deg;
  d.sun_el_deg = sun->observation.el_deg;
  if (const auto target = p_.source ? p_.source() : std::nullopt) {
    if (const auto seen = sky->observe(*target)) {
      d.source_az_deg = seen->observation.place.az_deg;
      d.source_el_deg = seen->observation.el_deg;
    }
  }
  d.freq_mhz = p_.sky.settings.freq_mhz.value_or(144.0);
  const double rate = moon->observation.place.range_rate_km_s.value_or(0.0);
  d.self_doppler_hz = astro::self_echo_doppler_hz(d.freq_mhz, rate);
  if (moon->dx_range_rate_km_s) {
    d.dx_doppler_hz = astro::dx_echo_doppler_hz(d.freq_mhz, rate, *moon->dx_range_rate_km_s);
  }
  if (last_unix_s_ && unix_s > *last_unix_s_) {
    const double minutes = (unix_s - *last_unix_s_) / 60.0;
    d.self_dfdt_hz_min = (d.self_doppler_hz - last_self_hz_) / minutes;
    d.dx_dfdt_hz_min = moon->dx_range_rate_km_s ? (d.dx_doppler_hz - last_dx_hz_) / minutes : 0.0;
  }
  last_unix_s_ = unix_s;
  last_self_hz_ = d.self_doppler_hz;
  last_dx_hz_ = d.dx_doppler_hz;
  d.transmitting = p_.transmitting && p_.transmitting();
  if (p_.pol_line) d.pol = pol_line(*moon, *sky);
  return eme::azel_dat_text(d);
}

void AzelDatExport::write_now() {
  if (writing_) return;
  const auto text = text_at(p_.unix_s());
  if (!text) return;
  writing_ = true;
  auto outcome = std::make_shared<Result<bool>>(fail("not written"));
  p_.offload(
      [outcome, write = p_.write, path = p_.path, text = *text] { *outcome = write(path, text); },
      [this, outcome] {
        writing_ = false;
        const std::string error = *outcome ? "" : outcome->error().message;
        if (error == last_error_) return;
        last_error_ = error;
        p_.log(error.empty() ? "azel.dat: writing " + p_.path : "azel.dat: not written: " + error);
      });
}

}  // namespace azt::app
