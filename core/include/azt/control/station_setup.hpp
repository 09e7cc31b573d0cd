#pragma once
// What a station is, to its controller, whatever drives and reads it: each axis's
// control and supervisor settings (the mount's rate and encoder step among them), the travel,
// the tick, the pointing corrections and what to do out of range. The daemon reads it from the
// configuration ([mount.*], [control], [geometry], [corrections]); every backend, the simulated
// one included, builds its one StationController from it.

#include <optional>

#include "azt/control/axis_controller.hpp"
#include "azt/control/axis_geometry.hpp"
#include "azt/control/corrections.hpp"
#include "azt/control/modes.hpp"
#include "azt/control/pol_axis.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/control/supervisor.hpp"

namespace azt::control {

struct StationSetup {
  AxisControlConfig az_control;  ///< lsb_deg: one step of the mount's azimuth encoder
  AxisControlConfig el_control;
  SupervisorConfig az_supervisor;
  SupervisorConfig el_supervisor;
  AzimuthRange az_range;
  ElevationRange el_range;
  double tick_s = 0.05;  ///< control tick (20 Hz, the daemon's default)
  /// The Offset / ± / UP / DWN / tilt settings, applied to every reading ([corrections]).
  PositionCorrections corrections;
  /// Where to go while the tracked target is outside the travel (below the horizon limit);
  /// nullopt holds the antenna where it is (ModeController's OutOfRangePolicy).
  std::optional<AzEl> park_when_out_of_range;
  /// The polarisation axis ([mount.pol]), if the station has one.
  std::optional<PolAxisConfig> pol;
  /// The elevation does not move ([mount.el] fixed_deg): the angle it is fixed at.
  std::optional<double> el_fixed_deg;

  /// Where the axes are believed to be before the first reading, when nothing says otherwise: 0°
  /// on each axis, or the nearest end of the travel. It decides only which turn a single-turn
  /// azimuth encoder's first reading is taken on (30° is 30°, not 390°, on a 0–450° mount).
  [[nodiscard]] AzEl believed_start() const;

  /// The station controller's configuration: these settings with PWM drives and single-turn
  /// sensors; a backend with other drives or sensors sets those fields.
  [[nodiscard]] StationControlConfig control_config() const;
};

}  // namespace azt::control
