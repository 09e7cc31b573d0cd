#include "config/pointing_config.hpp"

#include <cmath>
#include <string_view>

#include "config/config_file.hpp"

namespace azt::app {
namespace {

constexpr double kMaxTermDeg = 10.0;

double term(const ConfigSection& s, std::string_view key) {
  const double v = s.number(key).value_or(0.0);
  if (!(std::fabs(v) <= kMaxTermDeg)) s.fail(key, "must be within ±10°");
  return v;
}

}  // namespace

calibration::PointingTerms pointing_terms_from(const ConfigSection& s) {
  calibration::PointingTerms t;
  t.ia_deg = term(s, "ia_deg");
  t.ie_deg = term(s, "ie_deg");
  t.ca_deg = term(s, "ca_deg");
  t.npae_deg = term(s, "npae_deg");
  t.an_deg = term(s, "an_deg");
  t.aw_deg = term(s, "aw_deg");
  t.sag_deg = term(s, "sag_deg");
  return t;
}

calibration::PointingTerms station_pointing_from(const ConfigFile& file) {
  return pointing_terms_from(file.section(
      "pointing", {"ia_deg", "ie_deg", "ca_deg", "npae_deg", "an_deg", "aw_deg", "sag_deg"}));
}

calibration::PointingTerms mount_errors_from(const ConfigSection& sim) {
  const ConfigSection s =
      sim.child("mount_errors", {"az_offset_deg", "el_offset_deg", "collimation_deg", "nonperp_deg",
                                 "az_tilt_deg", "az_tilt_toward_deg", "el_sag_deg"});
  const double toward = s.number("az_tilt_toward_deg").value_or(0.0);
  if (!std::isfinite(toward)) s.fail("az_tilt_toward_deg", "must be a number of degrees");
  calibration::PointingTerms t = calibration::tilt_terms(term(s, "az_tilt_deg"), toward);
  t.ia_deg = term(s, "az_offset_deg");
  t.ie_deg = term(s, "el_offset_deg");
  t.ca_deg = term(s, "collimation_deg");
  t.npae_deg = term(s, "nonperp_deg");
  t.sag_deg = term(s, "el_sag_deg");
  return t;
}

}  // namespace azt::app
