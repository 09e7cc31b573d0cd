#pragma once
// Pointing through a satellite pass (docs/satellites.md). The plan is made once, before
// AOS, for the whole pass, so the antenna never re-plans mid-way:
//
//  * the mount azimuth is a path no faster than the mount's rate, found as the one that keeps the
//    beam nearest the satellite at its worst moment (a minimax over the pass, exact for the
//    azimuth: rate_limited_path.hpp). At each moment the beam is within e of the satellite for
//    azimuths within asin(sin e / cos el) of its azimuth, the elevation set to the best for that
//    azimuth, so near the zenith (the keyhole of a 90° mount) the path may lag and lead, and it
//    does so where cos(el) makes it cheapest;
//  * the azimuth may stand in any turn of the travel (on a 450° rotator a north crossing runs on
//    into the overlap); on a flip mount (elevation travel to 180°) in any half turn, since az +
//    180° at 180° − el is the same direction: a north crossing flown flipped, an overhead pass over
//    the top, a near-overhead pass tilted past the zenith rather than swung round;
//  * when no path stays within `loss_error_deg` of the satellite throughout (the pass sweeps more
//    than the travel), the plan loses the least time it can: one stretch in which the beam may be
//    off, placed where it is shortest (near the zenith, for high passes, where the azimuth is
//    cheapest to swing) and, among equally short ones, where the worst error is least. The mount
//    either swings once through its travel there or waits at a stop; the loss is reported before
//    AOS;
//  * the path begins in the turn nearest where the mount stands (least pre-positioning), and a
//    flip mount is flipped only where flipping helps.

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
  /// A moment of the pass is lost when the beam is further than this from the satellite: half
  /// the antenna's beamwidth (3 dB down).
  double loss_error_deg = 10.0;
  /// How long the azimuth takes to reach full speed from rest (the controller's soft start and
  /// the motor's response): a swing is that much longer at either end than its path, and the
  /// loss reported includes it.
  double ramp_s = 1.3;
  /// Elevation travel to 180°: the mount can look past the zenith.
  [[nodiscard]] bool can_flip() const { return el.max_deg >= 179.999; }
};

/// The geometry a pass is planned for: a station's travel and its axes' rates.
MountGeometry mount_geometry(const control::StationSetup& station);

struct PassPlan {
  bool flip = false;
  std::vector<MountPoint> track;  ///< at the sky samples' instants
  double az_travel_deg = 0.0;     ///< along the planned track
  double max_error_deg = 0.0;     ///< the worst pointing error the plan itself accepts
  double loss_error_deg = 10.0;   ///< the error beyond which a moment counts as lost
  double loss_s = 0.0;            ///< how long the plan points further than that
  double loss_from_s = 0.0;       ///< the first lost moment (when loss_s > 0)
  double loss_to_s = 0.0;         ///< the last lost moment
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
