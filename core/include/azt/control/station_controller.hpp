#pragma once
// Both axes of one station: readings in, motor duties out, once per control tick.
//
// The daemon and the simulation run the same object, so what the simulation measures is what the
// station does. It owns an AxisController and an AxisSupervisor per axis and turns a Demand (a sky
// position, a continuous move, or nothing) into mount targets through the travel planner.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "azt/control/axis_controller.hpp"
#include "azt/control/axis_geometry.hpp"
#include "azt/control/corrections.hpp"
#include "azt/control/driven_axis.hpp"
#include "azt/control/modes.hpp"
#include "azt/control/pol_axis.hpp"
#include "azt/control/supervisor.hpp"

namespace azt::control {

struct StationControlConfig {
  AxisControlConfig az_control;  ///< lsb_deg is the encoder step of the axis
  AxisControlConfig el_control;
  SupervisorConfig az_supervisor;  ///< lsb_deg is set from the controller's
  SupervisorConfig el_supervisor;
  AzimuthRange az_range;
  ElevationRange el_range;
  double tick_s = 0.05;
  AxisDriveConfig az_drive;
  AxisDriveConfig el_drive;
  /// The azimuth sensor reads the whole travel (a pot across a 450° rotator): its readings are
  /// mount angles, never resolved to the side nearest the last one as a single-turn encoder's are.
  bool az_absolute = false;
  /// The polarisation axis, if the station has one: PortedStation drives it beside the two
  /// axes this controller drives (pol_axis.hpp).
  std::optional<PolAxisConfig> pol;
  /// A station whose elevation does not move (a fixed-elevation EME array; 0 for an
  /// azimuth-only rotator): the elevation is this angle, never read, driven or supervised, and
  /// the station needs no elevation drive or sensor.
  std::optional<double> el_fixed_deg;
};

/// What to apply until the next tick. PWM axes: the duty. Relay axes: +1, −1 or 0 (forward,
/// reverse, released). Setpoint axes: the angle to send (mount degrees) in *_setpoint_deg; their
/// duty is the direction the box is expected to drive, for display.
struct Duties {
  double az = 0.0;
  double el = 0.0;
  std::optional<double> az_setpoint_deg;
  std::optional<double> el_setpoint_deg;
};

/// The travel-end switches (docs/hardware.md): normally closed, so a broken wire reads as tripped.
/// A tripped switch stops the drive towards it at once, without a soft stop, and still lets the
/// axis move away from it. Forward (positive duty) is clockwise and up.
struct LimitSwitches {
  bool az_ccw = false;  ///< azimuth at its counter-clockwise end (decreasing angle)
  bool az_cw = false;
  bool el_down = false;
  bool el_up = false;
  friend bool operator==(const LimitSwitches&, const LimitSwitches&) = default;
};

/// One axis's travel, mount degrees.
struct AxisTravel {
  double min_deg = 0.0;
  double max_deg = 0.0;
};

class StationController {
 public:
  /// `start_mount` is where the axes are believed to be before the first reading (it resolves
  /// the overlap side of a single-turn azimuth encoder).
  StationController(const StationControlConfig& config, AzEl start_mount);

  /// Encoder angles 0..360 as read at `now_s`. The position corrections are applied first (offset,
  /// user correction, tilt: corrections.hpp); then azimuth is placed on the mount (the equivalent
  /// angle nearest the last one) and elevation above 270 is below the horizon. A fixed elevation
  /// (StationControlConfig::el_fixed_deg) ignores `el_deg`: the fixed angle stands in for it.
  void on_encoder_reading(double now_s, double az_deg, double el_deg);

  /// New corrections take effect at once: the present position is re-expressed under them (the
  /// supervisors are told it is a calibration, not a jump), so the controller moves the antenna by
  /// the change, as the seed's ± / UP / DWN buttons do.
  void set_corrections(const PositionCorrections& corrections);
  [[nodiscard]] const PositionCorrections& corrections() const { return corrections_; }
  /// The last encoder angles as read, before any correction (the seed's "as read" display).
  [[nodiscard]] const std::optional<AzEl>& encoder_reading() const { return last_encoder_; }

  /// One control tick: the duties to apply until the next. `rate` is the target's sky rate
  /// (deg/s), used as feed-forward while tracking.
  Duties tick(double now_s, const Demand& demand, const AzEl& rate_deg_s);

  /// The switches changed (an input edge, between ticks): returns the duties to apply now, with a
  /// drive towards a tripped switch already at zero.
  Duties set_limits(const LimitSwitches& limits);
  [[nodiscard]] const LimitSwitches& limits() const { return limits_; }
  /// What the drives should apply now (as the last tick, set_limits() or a stop left it).
  [[nodiscard]] Duties duties() const;

  /// The sky position (azimuth 0..360; a flip mount past the zenith is turned back into sky
  /// terms), or nullopt while a reading is stale or an axis is faulted.
  [[nodiscard]] std::optional<AzEl> sky_position(double now_s) const;
  [[nodiscard]] AxisStatus az() const { return az_.status(); }
  [[nodiscard]] AxisStatus el() const { return el_.status(); }
  [[nodiscard]] bool faulted() const;
  /// Motor starts since construction (a relay closing, or a PWM move beginning).
  [[nodiscard]] std::uint64_t starts_az() const { return az_.starts(); }
  [[nodiscard]] std::uint64_t starts_el() const { return el_.starts(); }
  [[nodiscard]] const StationControlConfig& config() const { return config_; }
  /// The elevation does not move (StationControlConfig::el_fixed_deg).
  [[nodiscard]] bool el_fixed() const { return config_.el_fixed_deg.has_value(); }

  /// Stops both motors now (E-stop or shutdown) and latches an E-stop fault.
  void emergency_stop(double now_s, std::string_view reason = "emergency stop input active");
  /// Clears latched faults (the operator's explicit reset).
  void clear_faults();
  /// This tick's motor readings per axis (driven_axis.hpp): a trip stops that axis at once.
  void on_motor_readings(double now_s, const MotorReadings& az, const MotorReadings& el);

  /// Pulse-counted axes (AxisDriveConfig::pulses), `axis` 0 azimuth, 1 elevation: this tick's
  /// edges, before tick(). Such an axis reads its count, not on_encoder_reading()'s angle (the
  /// count is a mount angle once homed: the corrections do not apply to it).
  void on_pulse_edges(double now_s, std::size_t axis, std::span<const ports::PulseEdge> edges);
  /// Starts homing `axis` (0 az, 1 el); why not (no pulse sensor, a fault to clear first).
  std::optional<std::string> home(double now_s, std::size_t axis, bool home_closed);
  /// Ends every homing in progress (a STOP): see DrivenAxis::stop_homing.
  void stop_homing(double now_s, std::string_view reason);
  /// The pulse sensor of `axis` (0 az, 1 el); null when it has none or the elevation is fixed.
  [[nodiscard]] const PulseAxis* pulses(std::size_t axis) const;

 private:
  /// Where a continuous move on one axis is going: its direction, and below full speed the goal
  /// that moves at the asked speed (tick()).
  struct JogGoal {
    int direction = 0;
    double goal_deg = 0.0;
  };
  /// The axis's target for a continuous move, and `rate_deg_s` its rate (fed forward).
  std::optional<double> jog_target(JogGoal& jog, const DrivenAxis& axis, int direction,
                                   double speed, const AxisTravel& travel,
                                   double& rate_deg_s) const;

  StationControlConfig config_;
  DrivenAxis az_;
  DrivenAxis el_;
  PositionCorrections corrections_;
  LimitSwitches limits_;
  std::optional<AzEl> last_encoder_;  ///< the last raw encoder angles, to re-express on a change
  JogGoal az_jog_;
  JogGoal el_jog_;
};

}  // namespace azt::control
