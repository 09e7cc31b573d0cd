#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "azt/control/axis_controller.hpp"
#include "azt/control/axis_geometry.hpp"
#include "azt/control/brake.hpp"
#include "azt/control/modes.hpp"
#include "azt/control/motor_trips.hpp"
#include "azt/control/station_controller.hpp"
#include "azt/control/station_setup.hpp"
#include "azt/control/supervisor.hpp"
#include "azt/proto/hub_decoder.hpp"
#include "azt/sim/axis_plant.hpp"
#include "azt/sim/plant_setup.hpp"
#include "azt/sim/simulated_hub.hpp"

namespace azt::sim {

/// One simulated station: the station as its controller knows it (the mount's rates and encoder
/// steps, the travel, the tick, the corrections: what a real station of this mount would run
/// with) and the plants it drives, in virtual time.
/// What the controller is told of one simulated axis's brake and motor (the `sim` backend's
/// [sim.az] brake_release_s … and temperature_limit_c, as a real station's [hardware.az]): the
/// plants' brake and winding (PlantSetup::brakes, ::thermal) are the truth it drives and reads,
/// these the settings it drives and reads them with. Empty: the axis has none.
struct AxisMotorControl {
  std::optional<control::BrakeConfig> brake;
  std::optional<control::MotorTripsConfig> trips;
};

struct StationSimSetup {
  control::StationSetup station;
  PlantSetup plant;
  std::array<AxisMotorControl, 2> motors{};  ///< azimuth, elevation
};

/// The simulated station controller's configuration: the station setup's, with the encoder steps
/// of the plants it reads and the axes' brake and motor trips (`motors`). Real stations use
/// control::StationSetup::control_config().
control::StationControlConfig station_control_config(const StationSimSetup& setup);

/// The sky position to follow at `t_s` seconds after the start (nullopt: nothing to follow).
using SkyTrack = std::function<std::optional<control::AzEl>(double t_s)>;

/// The polarisation axis's feed angle at `t_s` seconds after the start (control/pol_target.hpp's
/// pol_feed_deg; nullopt: the axis holds).
using PolTrack = std::function<std::optional<double>(double t_s)>;

struct PolTracking {
  PolTrack track;  ///< empty: a pol axis, if the station has one, holds
  /// What the error is measured against (an outside program's angles); empty: `track` itself.
  PolTrack reference;
  /// A settling allowance: after the station's pol target jumps by more than 1° in one tick (a
  /// change between receive and transmit, a turn to the other end of the travel), the error is not
  /// counted for this long.
  double settle_s = 0.0;
};

struct AxisMetrics {
  double rms_error_deg = 0.0;
  double max_error_deg = 0.0;
  std::uint64_t starts = 0;
  double starts_per_hour = 0.0;
  double overshoot_deg = 0.0;
  double travel_deg = 0.0;  ///< how far the target moved along this axis while tracked
};

struct SimResult {
  AxisMetrics az;
  AxisMetrics el;
  double rms_error_deg = 0.0;         ///< both axes, per-axis errors pooled
  double max_error_deg = 0.0;         ///< the larger axis error (true shaft against the target)
  std::optional<double> acquired_s;   ///< first time both axes were within window + 2 LSB
  std::optional<double> slew_time_s;  ///< slew scenario: until both axes came to rest there
  double slew_min_time_s = 0.0;       ///< distance / max rate of the slower axis
  double simulated_s = 0.0;
  control::AzEl final_position;     ///< the true shafts at the end of the run
  std::vector<std::string> faults;  ///< "az: stall at 12.3 s: …"
  /// The largest |duty| applied to an axis after its supervisor latched a fault (must be 0: the
  /// motors stop in the tick that detects it).
  double max_duty_after_fault = 0.0;
  /// The time the motor was driven while its axis's brake still held (azimuth, elevation; 0
  /// without a brake plant): a controller's brake_release_s shorter than the brake's own lift.
  std::array<double, 2> brake_pulled_against_s{};
  proto::HubCounters hub{};  ///< the decoder's counters after the run
  /// The polarisation axis (with a pol plant and a PolTracking track): the true shaft against the
  /// feed angle, folded as a linear polarisation, from its acquisition (within window + 2 LSB)
  /// on, outside the settling allowances.
  std::optional<AxisMetrics> pol;
  double pol_settling_s = 0.0;  ///< time left uncounted as settling
  double pol_counted_s = 0.0;   ///< time whose error is in `pol`
};

/// Tracks `sky` for `duration_s`. Errors are the true shaft positions against the target, counted
/// from acquisition on, and not while the target is below the elevation range (the axes hold).
/// The station is the daemon's (control::PortedStation) over the simulated station's ports, read
/// through `hub` (nullptr: the plain model of setup.plant, simulated_station.hpp).
SimResult simulate_tracking(const StationSimSetup& setup, const SkyTrack& sky, double duration_s,
                            std::unique_ptr<SimulatedHub> hub = nullptr,
                            const PolTracking& pol = {});

/// Slews from the plants' start positions to `to` and measures time and overshoot.
SimResult simulate_slew(const StationSimSetup& setup, control::AzEl to, double max_duration_s,
                        std::unique_ptr<SimulatedHub> hub = nullptr);

}  // namespace azt::sim
