#include "config/pointing_config.hpp"

#include <cmath>
#include <string_view>

#include "config/config_file.hpp"

namespace azt::app {
namespace {

/// A term of the model, within ±10° (the schema).
double term(const ConfigSection& s, std::string_view key) { return s.number(key).value_or(0.0); }

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
  return pointing_terms_from(file.section("pointing"));
}

calibration::PointingTerms mount_errors_from(const ConfigSection& sim) {
  const ConfigSection s = sim.child("mount_errors");
  const double toward = s.number("az_tilt_toward_deg").value_or(0.0);
  calibration::PointingTerms t = calibration::tilt_terms(term(s, "az_tilt_deg"), toward);
  t.ia_deg = term(s, "az_offset_deg");
  t.ie_deg = term(s, "el_offset_deg");
  t.ca_deg = term(s, "collimation_deg");
  t.npae_deg = term(s, "nonperp_deg");
  t.sag_deg = term(s, "el_sag_deg");
  return t;
}

}  // namespace azt::app
