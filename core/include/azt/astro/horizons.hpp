#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "azt/astro/time_scales.hpp"
#include "azt/astro/vec3.hpp"
#include "azt/util/result.hpp"

namespace azt::astro {

/// A spacecraft's geocentric states read from a JPL Horizons vector table, interpolated between
/// the listed instants. The controller does light time, aberration, the topocentric reduction and
/// refraction itself (as for the Moon), so the table must be geometric, geocentric
/// (CENTER='500@399') and in the ICRF equatorial frame (REF_SYSTEM='ICRF', REF_PLANE='FRAME');
/// anything else is refused rather than converted. Immutable once parsed.
class SpacecraftTable {
 public:
  struct Node {
    JulianDate tdb;
    PosVel state;  ///< Geocentric ICRF, au and au/day.
  };

  /// Parses the text of a Horizons EPHEM_TYPE='VECTORS' reply (the API's `result`, or the e-mail
  /// or web output): CSV_FORMAT YES or NO, VEC_TABLE 2 or 3 (LT, RG, RR are ignored), OUT_UNITS
  /// KM-S, KM-D or AU-D. Errors name the header line or record line (1-based) and the problem: a
  /// frame, plane, centre or correction the controller cannot use, missing $$SOE/$$EOE, a bad
  /// number, fewer than two records, times not strictly increasing.
  static Result<SpacecraftTable> parse_horizons_vectors(std::string_view text);

  /// "Target body name" from the header, without the `{source: …}` note.
  [[nodiscard]] const std::string& target() const { return target_; }
  [[nodiscard]] const std::vector<Node>& nodes() const { return nodes_; }

  /// State at a TDB instant (TT may be passed: they differ by < 2 ms), by cubic Hermite
  /// interpolation on position and velocity between the two bracketing records; the records may
  /// be unevenly spaced. Error outside the tabulated span, naming it.
  [[nodiscard]] Result<PosVel> at(const JulianDate& tdb) const;

 private:
  SpacecraftTable() = default;

  std::string target_;
  std::vector<Node> nodes_;
  std::vector<double> offset_days_;  ///< Node times minus the first node's, for the search.
};

/// The site a Horizons observer table was computed for ("Center geodetic :" line), so the caller
/// can check it against its station. Longitude is east-positive, normalised to [−180, 180).
struct HorizonsSite {
  double lon_east_deg = 0.0;
  double lat_deg = 0.0;
  double alt_km = 0.0;
};

/// One interpolated row of an observer table.
struct ObserverLook {
  double az_deg = 0.0;  ///< Apparent (airless) azimuth, from north through east, [0, 360).
  double el_deg = 0.0;  ///< Apparent (airless) elevation.
  double range_km = 0.0;
  double range_rate_km_s = 0.0;  ///< Positive receding.
};

/// Az/el, range and range rate read from a Horizons EPHEM_TYPE='OBSERVER' table for one site,
/// for users who already have such files (vector tables are preferred: they serve any station).
/// Immutable once parsed.
class ObserverTable {
 public:
  /// Parses the text of a Horizons observer reply made with CSV_FORMAT='YES', ANG_FORMAT='DEG' and
  /// quantities 4 (Azi_(a-app), Elev_(a-app)) and 20 (delta, deldot); other columns are ignored.
  /// Times come from Date_________JDUT, else from the Date__(UT)__HR:MN… calendar column. delta
  /// is in au unless the footer's delta paragraph says "Units: KM" (RANGE_UNITS='KM'). Errors name
  /// the line: not CSV, a missing column, n.a. (geocentric table), a bad number, fewer than two
  /// rows, times not strictly increasing, no $$SOE/$$EOE.
  static Result<ObserverTable> parse_horizons_observer(std::string_view text);

  [[nodiscard]] const std::string& target() const { return target_; }
  [[nodiscard]] const HorizonsSite& site() const { return site_; }
  [[nodiscard]] std::size_t size() const { return times_days_.size(); }

  /// Look at a UTC instant: a cubic through the four nearest rows (fewer at the ends of a short
  /// table), azimuth unwrapped across north first. Error outside the tabulated span, naming it.
  [[nodiscard]] Result<ObserverLook> at(const UtcInstant& utc) const;

 private:
  ObserverTable() = default;

  std::string target_;
  HorizonsSite site_;
  JulianDate first_utc_;
  std::vector<double> times_days_;  ///< Row times minus the first row's.
  std::vector<ObserverLook> rows_;
};

}  // namespace azt::astro
