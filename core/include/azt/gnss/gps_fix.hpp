#pragma once
// What a GPS receiver reports, as gpsd's TPV and SKY reports carry it (docs/gps.md): the types
// the gpsd adapter (azt/linux/gpsd_client.hpp) hands the pure monitor and site survey.

#include <optional>
#include <vector>

namespace azt::gnss {

enum class FixMode { None, Fix2d, Fix3d };

struct GpsSatellite {
  int prn = 0;
  double el_deg = 0.0;
  double az_deg = 0.0;
  double snr_dbhz = 0.0;
  bool used = false;  ///< in the position solution
};

/// gpsd's TPV: angles in degrees, altitude above mean sea level, time as UTC seconds since 1970.
struct GpsFix {
  FixMode mode = FixMode::None;
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  std::optional<double> alt_m;
  std::optional<double> time_unix_s;
};

/// gpsd's SKY.
struct GpsSky {
  int sats_used = 0;
  int sats_visible = 0;
  std::optional<double> hdop;
  std::vector<GpsSatellite> satellites;
};

/// A place on the WGS84 ellipsoid (altitude above mean sea level).
struct Site {
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  double alt_m = 0.0;
};

/// Great-circle distance in metres between two sites' latitudes and longitudes (haversine on
/// the mean Earth radius, 6371008.8 m: within 0.5 % of the ellipsoid's, plenty to tell a moved
/// antenna from a wandering fix); altitude is ignored.
double ground_distance_m(const Site& a, const Site& b);

}  // namespace azt::gnss
