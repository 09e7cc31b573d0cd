#pragma once
// Mean orbital elements as SGP4 takes them (docs/satellites.md): what a TLE or a CCSDS OMM carries,
// in the TLE's own units so that both parsers and the propagator agree on one structure.

#include <cstdint>
#include <string>

namespace azt::orbit {

struct Elements {
  std::string name;             ///< line 0 of a three-line set, OMM OBJECT_NAME; may be empty
  std::string catalog;          ///< NORAD catalogue number as text ("25544"; alpha-5 "A0001")
  std::string intl_designator;  ///< "98067A"; may be empty
  char classification = 'U';
  /// The epoch as a UTC Julian date split in two for precision: whole + fraction, e.g.
  /// 2460000.5 + 0.123456789.
  double epoch_jd = 0.0;
  double epoch_jd_frac = 0.0;
  double mean_motion_dot = 0.0;   ///< ṅ/2, rev/day² (TLE line 1 columns 34–43)
  double mean_motion_ddot = 0.0;  ///< n̈/6, rev/day³
  double bstar = 0.0;             ///< drag term, 1/earth radii
  double inclination_deg = 0.0;
  double raan_deg = 0.0;  ///< right ascension of the ascending node
  double eccentricity = 0.0;
  double arg_perigee_deg = 0.0;
  double mean_anomaly_deg = 0.0;
  double mean_motion_rev_day = 0.0;
  std::int64_t element_set_no = 0;
  std::int64_t rev_at_epoch = 0;

  /// The name if there is one, else the catalogue number (for messages and lists).
  [[nodiscard]] std::string label() const { return name.empty() ? catalog : name; }
};

}  // namespace azt::orbit
