#pragma once
// Pointing through a satellite pass (issue 7 §2). The plan is made once, at AOS, for the whole
// pass, so the antenna never unwinds mid-way:
//
//  * the mount azimuth is the sky track unwrapped (continuous) and shifted by whole turns to fit
//    the rotator's travel, choosing, among the shifts that fit, the one nearest where the mount
//    stands (least pre-positioning). A pass that sweeps more than any shift holds (north-crossing
//    passes on a 0–360° rotator, some on 450°) waits at the stop for the part it cannot reach:
//    an accepted error, never an unwind;
//  * on a flip mount (elevation travel to 180°) the pass may be flown flipped, az + 180° and
//    el' = 180° − el, which moves a crossing of the north stop to the south; or normal up to the
//    highest point and flipped after it, which takes an overhead pass over the top instead of
//    swinging the azimuth;
//  * where the track asks more than the mount's rates (the keyhole near the zenith of a 90°
//    mount), the path is rate limited forwards and backwards in time and the two averaged: the
//    swing starts early by half as much as it ends late, centred on the pass's highest point,
//    where cos(el) makes an azimuth error cost least.
// The option with the least worst-case pointing error wins; then the least pre-positioning; then
// not flipping.

#include <vector>

#include "azt/control/axis_geometry.hpp"
#include "azt/control/station_setup.hpp"
#include "azt/util/result.hpp"

namespace azt::track {

struct SkyPoint {
  double t_s = 0.0;
  double az_deg = 0.0;
  double el_deg = 0.0;
};

struct MountPoint {
  double t_s = 0.0;
  double az_deg = 0.0;  ///< mount azimuth (may count past 360)
  double el_deg = 0.0;  ///< mount elevation (past 90 when flipped)
};

struct MountGeometry {
  control::AzimuthRange az;
  control::ElevationRange el;
  double max_az_rate_deg_s = 6.0;
  double max_el_rate_deg_s = 3.0;
  /// Elevation travel to 180°: the mount can look past the zenith.
  [[nodiscard]] bool can_flip() const { return el.max_deg >= 179.999; }
};

/// The geometry a pass is planned for: a station's travel and its axes' rates.
MountGeometry mount_geometry(const control::StationSetup& station);

struct PassPlan {
  bool flip = false;
  std::vector<MountPoint> track;  ///< at the sky samples' instants
  double az_travel_deg = 0.0;     ///< along the planned track
  double max_error_deg = 0.0;     ///< the worst pointing error the plan itself accepts (keyhole)
  /// The planned mount position at `t_s`, interpolated; the first point before the pass (where to
  /// pre-position), the last after it.
  [[nodiscard]] MountPoint at(double t_s) const;
};

/// Plans a pass sampled from AOS to LOS (increasing times, at least two samples; a second or two
/// apart is plenty), for a mount standing at `current_az_mount_deg`.
Result<PassPlan> plan_pass(const std::vector<SkyPoint>& sky, const MountGeometry& mount,
                           double current_az_mount_deg);

/// The angle between two directions given as azimuth/elevation, degrees.
double separation_deg(double az1_deg, double el1_deg, double az2_deg, double el2_deg);

/// Where a mount position points in the sky (a flipped elevation turned back).
SkyPoint mount_to_sky(const MountPoint& m);

}  // namespace azt::track
