#pragma once

#include "azt/util/result.hpp"

namespace azt::astro {

/// A station on the WGS84 ellipsoid. North latitude and east longitude are positive; height is
/// above the ellipsoid in metres (GPS height; within ~50 m of sea level height, which moves the
/// Moon by < 0.03″).
struct Observer {
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  double height_m = 0.0;

  /// Validates: latitude in [−90, 90], longitude in [−180, 180], height in [−500, 10000] m, all
  /// finite. The error names the field and the allowed range.
  static Result<Observer> make(double lat_deg, double lon_deg, double height_m);
};

}  // namespace azt::astro
