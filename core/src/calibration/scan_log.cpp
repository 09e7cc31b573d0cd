#include "azt/calibration/scan_log.hpp"

#include <cmath>

namespace azt::calibration {
namespace {

double wrap_180(double deg) { return std::remainder(deg, 360.0); }

/// The peak over the fit's noise, both linear over the baseline; nullopt without a noise.
std::optional<double> snr_db(const ScanFit& fit) {
  const double noise = std::pow(10.0, fit.noise_db / 10.0) - 1.0;
  const double peak = std::pow(10.0, fit.peak_db / 10.0) - 1.0;
  if (!(noise > 0.0) || !(peak > 0.0)) return std::nullopt;
  return 10.0 * std::log10(peak / noise);
}

std::optional<double> positive(double value) {
  return value > 0.0 ? std::optional<double>(value) : std::nullopt;
}

ScanLogEntry entry(const FinishedScan& scan, const control::PositionCorrections& in_use,
                   const control::AzEl& sky, const astro::UtcInstant& utc, Measured measured) {
  const control::AzEl mount = mount_on_source(in_use, sky, scan.fit.peak);
  ScanLogEntry e;
  e.utc = utc;
  e.source = scan.source;
  e.az_deg = sky.az_deg;
  e.el_deg = sky.el_deg;
  e.daz_deg = wrap_180(mount.az_deg - sky.az_deg);
  e.del_deg = mount.el_deg - sky.el_deg;
  e.measured = measured;
  e.sigma_xel_deg = positive(scan.fit.peak_std.xel_deg);
  e.sigma_el_deg = positive(scan.fit.peak_std.el_deg);
  e.snr_db = snr_db(scan.fit);
  e.rise_db = scan.fit.peak_db;
  const double width = 0.5 * (scan.fit.width_xel_deg + scan.fit.width_el_deg);
  e.beamwidth_deg = positive(deconvolved_beamwidth_deg(width, scan.source_size_deg));
  return e;
}

}  // namespace

std::string_view to_string(Measured m) {
  switch (m) {
    case Measured::Both:
      return "both";
    case Measured::Az:
      return "az";
    case Measured::El:
      return "el";
  }
  return "both";
}

Result<Measured> parse_measured(std::string_view text) {
  for (const Measured m : {Measured::Both, Measured::Az, Measured::El}) {
    if (text == to_string(m)) return m;
  }
  return fail("measured must be both, az or el");
}

control::AzEl mount_on_source(const control::PositionCorrections& in_use, const control::AzEl& sky,
                              const SkyOffset& peak) {
  control::AzEl believed = apply_offset(sky, peak);
  believed.el_deg -= in_use.tilt.correction_el_deg(believed.az_deg);
  believed.az_deg += in_use.user.az_deg();
  believed.el_deg += in_use.user.el_deg();
  return mount_for_sky(believed, in_use.model).value_or(believed);
}

std::vector<ScanLogEntry> log_entries(const FinishedScan& scan,
                                      const control::PositionCorrections& in_use) {
  if (scan.kind != ScanKind::Cross) {
    return {entry(scan, in_use, scan.sky_el, scan.utc_el, Measured::Both)};
  }
  return {entry(scan, in_use, scan.sky_xel, scan.utc_xel, Measured::Az),
          entry(scan, in_use, scan.sky_el, scan.utc_el, Measured::El)};
}

std::vector<PointingObservation> observations_from_log(const std::vector<ScanLogEntry>& log) {
  std::vector<PointingObservation> out;
  out.reserve(log.size());
  for (const ScanLogEntry& e : log) {
    PointingObservation o;
    o.sky = {e.az_deg, e.el_deg};
    o.mount = {e.az_deg + e.daz_deg, e.el_deg + e.del_deg};
    o.has_xel = e.measured != Measured::El;
    o.has_el = e.measured != Measured::Az;
    o.sigma = {e.sigma_xel_deg.value_or(0.0), e.sigma_el_deg.value_or(0.0)};
    o.weight = e.weight;
    out.push_back(o);
  }
  return out;
}

}  // namespace azt::calibration
