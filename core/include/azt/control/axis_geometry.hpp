#pragma once

#include <optional>

#include "azt/util/result.hpp"

namespace azt::control {

/// The azimuth travel of a rotator in its own (mount) coordinate, which keeps counting past 360°
/// on overlap rotators: 0–360, 0–450 (a 90° overlap), −180…+540, or a 450° range starting at a
/// chosen point (e.g. 270…720 for a stop in the west). The mount angle modulo 360 is the sky
/// azimuth.
struct AzimuthRange {
  double min_deg = 0.0;
  double max_deg = 360.0;

  /// Validates: finite, max − min in [360, 720] (less cannot reach every azimuth; more is no
  /// rotator we know).
  static Result<AzimuthRange> make(double min_deg, double max_deg);
};

/// Elevation travel: 0–90 for az/el rotators, 0–180 for flip mounts (the pass planner of the
/// satellite issue decides when to flip).
struct ElevationRange {
  double min_deg = 0.0;
  double max_deg = 90.0;
  static Result<ElevationRange> make(double min_deg, double max_deg);
};

/// Wraps any angle to [0, 360).
double wrap_360(double deg);

/// The mount azimuth to drive to for a sky azimuth: among the equivalent angles az + k·360 inside
/// the range, the one nearest the present mount position — the shortest legal path, which never
/// crosses the stop because the mount angle is continuous inside the range. On overlap rotators
/// this keeps a track that crosses north on the side it is on instead of unwinding.
double plan_azimuth(double current_mount_deg, double target_sky_deg, const AzimuthRange& range);

/// The elevation to drive to, or nullopt when the target is outside the elevation range (below
/// the horizon limit, or above the top of a 0–90 mount's travel).
std::optional<double> plan_elevation(double target_el_deg, const ElevationRange& range);

}  // namespace azt::control
