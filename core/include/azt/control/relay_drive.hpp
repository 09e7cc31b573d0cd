#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::control {

// On/off drives (seed 002: the Alliance HD-73 azimuth rotor through "a couple of relays … for
// clockwise and counter-clockwise rotation"; the elevation actuator through two relays, "One relay
// switches power to the actuator, while the other controls the DC polarity for UP/DOWN").
//
// A relay cannot ramp: the motor starts at full current and, when released, coasts. Controllers
// that switch relays on every small error chatter, wear contacts and blow fuses (reference/
// reliability-and-security.md §1.8 and §2.4: remoteRotator #4, pyrot's reversal timer "I blew a
// fuse", satnogs-client #269 "burned relays"). Hence the hysteresis (start beyond L2, stop within
// 1 LSB), a minimum on-time and a dead time before any reversal.

/// What the relays of one axis do this tick. Forward is towards increasing angle (clockwise
/// azimuth seen from above, rising elevation), the same sign as a positive duty of AxisController.
enum class RelayCommand : std::uint8_t { Off, Forward, Reverse };

std::string_view to_string(RelayCommand command);

/// How one relay-driven axis is switched. Angles are mount degrees, times seconds.
struct RelayDriveConfig {
  /// The movement window (seed 000's "Antenna Movement Window"). Up to 10°, wider than the PWM
  /// controller's 2°: relay rotors are usually run with a few degrees (K3NG's 3° azimuth
  /// tolerance; satnogs-client #269 proposes ≥ 2°, because wind alone moves a G-5500 about 1°).
  double window_deg = 1.0;
  /// One step of the position reading. Default: seed 002's pots on the BX-24's 10-bit ADC,
  /// "360/1024 or 0.35 degree" (its elevation, 0–90° over 0–1.25 V, has the same step).
  double lsb_deg = 360.0 / 1024;
  /// How far the axis runs on after its relay opens at full speed (measure it: release at full
  /// speed and read how far it goes). The drive releases when the remaining distance is at most
  /// coast_deg + 1 LSB, so the axis coasts into the goal instead of past it. A short move never
  /// reaches full speed, coasts less and so stops short of the goal, never beyond it.
  double coast_deg = 0.0;
  /// Once energised, a relay stays on at least this long (contact wear and the motor's start
  /// current: a start is the costly part). Default 0.1 s: ArduPilot AntennaTracker's
  /// ONOFF_YAW_MINT, and the chatter test R19's "every on-pulse ≥ 100 ms".
  double min_on_s = 0.1;
  /// After a release, both directions stay off this long before the other direction may be
  /// energised: never reverse a motor under load or before its brake has set (seed 002 switches
  /// DC polarity; K3NG waits 3 s; R19 asks ≥ 500 ms). Must be > 0.
  double reversal_dead_s = 0.5;
  /// After a release, no start in either direction for this long (0: none beyond min_on_s).
  double min_off_s = 0.0;
  /// Lead a moving target: aim window_deg beyond it in the direction it moves (as AxisController
  /// does), so it crosses the whole window before the next start. Needs the target's rate:
  /// without it the axis aims at the target itself, stops just short of it (a short move coasts
  /// less than coast_deg) and so starts again after less than L2 of target travel.
  bool lead = true;

  /// Validates every field; errors name it.
  static Result<RelayDriveConfig> make(const RelayDriveConfig& c);
  /// L2 = window + 1 LSB: no relay closes while |target − position| ≤ L2 (the same start
  /// threshold as AxisControlConfig, so the two drives behave alike at rest).
  [[nodiscard]] double start_threshold_deg() const { return window_deg + lsb_deg; }
  /// The release distance: coast + 1 LSB before the goal.
  [[nodiscard]] double stop_distance_deg() const { return coast_deg + lsb_deg; }
};

/// The on/off controller of one axis: a pure state machine, time a parameter (seconds of a
/// monotonic clock, the same clock for every call).
///
/// At rest it waits until |target − position| > L2, then energises towards the target. It
/// releases when the remaining distance to the goal, measured in the direction of travel, is at
/// most coast + 1 LSB — which includes having passed the goal (the error changed sign). The goal
/// is the target, or with `lead` and a moving target, window_deg beyond it.
///
/// Timing rules, in order of precedence:
/// 1. halt() and invalid inputs release at once (safety overrides the minimum on-time).
/// 2. A relay, once closed, stays closed for min_on_s. Consequence: if the goal is reached
///    early (a short move, or the target jumped back) the axis runs on for the rest of min_on_s
///    and then coasts: a minimum pulse moves it about rate·min_on_s + its coast. Keep that below
///    the window (ArduPilot sizes its deadband as rate × minimum on-time) or a minimum pulse can
///    overshoot past L2 and call for a reversal.
/// 3. After a release, the same direction may restart after min_off_s, the other direction
///    after max(min_off_s, reversal_dead_s). The releasing tick is always Off, so Forward and
///    Reverse are never returned on consecutive ticks.
///
/// At construction the drive assumes the relays were released just before the first tick (a
/// restart after a crash may find the motor still turning), in an unknown direction: the first
/// start waits max(min_off_s, reversal_dead_s) from the first update.
class RelayDrive {
 public:
  /// Precondition: RelayDriveConfig::make(config).ok().
  explicit RelayDrive(const RelayDriveConfig& config) : config_(config) {}

  /// One control tick at `now_s`. `target_rate_deg_s` is how fast the target moves (for the
  /// lead; 0 for a fixed target). A non-finite argument, or a time earlier than the previous
  /// tick's, releases at once as halt() does.
  RelayCommand update(double target_deg, double position_deg, double now_s,
                      double target_rate_deg_s = 0.0);

  /// Releases at once, whatever the minimum on-time (safety stops). The dead times still run
  /// from now_s; a non-finite now_s makes them run from the next update instead. Like
  /// AxisController::halt() it does not latch: the next update may start again once the dead
  /// times allow, so a latched fault is the supervisor's to hold (stop calling update).
  void halt(double now_s);

  [[nodiscard]] RelayCommand command() const { return command_; }
  /// Starts since construction (each is a relay closing on a motor at rest).
  [[nodiscard]] std::uint64_t starts() const { return starts_; }
  /// Starts in the direction opposite to the previous start: a count that keeps rising on a
  /// steadily moving target means hunting.
  [[nodiscard]] std::uint64_t reversals() const { return reversals_; }
  [[nodiscard]] const RelayDriveConfig& config() const { return config_; }

 private:
  [[nodiscard]] double goal_deg(double target_deg, double target_rate_deg_s) const;
  [[nodiscard]] bool may_start(RelayCommand wanted, double now_s) const;
  RelayCommand run(double target_deg, double position_deg, double now_s, double rate_deg_s);
  RelayCommand try_start(double target_deg, double position_deg, double now_s);
  void release(double now_s);

  RelayDriveConfig config_;
  RelayCommand command_ = RelayCommand::Off;
  RelayCommand last_direction_ = RelayCommand::Off;  ///< of the last start; Off: unknown
  double energised_at_s_ = 0.0;
  std::optional<double> released_at_s_;  ///< empty: the release time is set by the next update
  std::optional<double> last_now_s_;
  std::uint64_t starts_ = 0;
  std::uint64_t reversals_ = 0;
};

/// Two relays for a DC actuator (seed 002's elevation): `power` switches the supply, `reverse`
/// selects the polarity (false: Forward). The polarity relay must never switch while current
/// flows (it would break the motor current, arc, and reverse a running motor).
struct PowerPolarity {
  bool power = false;
  bool reverse = false;

  friend bool operator==(const PowerPolarity&, const PowerPolarity&) = default;
};

struct PowerPolarityConfig {
  /// Power off at least this long before the polarity relay may switch. Use the drive's
  /// reversal_dead_s: the actuator must have stopped, not just lost its supply.
  double dead_s = 0.5;
  /// The polarity relay must have been still this long before power closes (operate time and
  /// contact bounce are milliseconds to tens of milliseconds for common power relays).
  double settle_s = 0.05;

  /// Validates: dead_s in (0, 60] s, settle_s in [0, 1] s.
  static Result<PowerPolarityConfig> make(const PowerPolarityConfig& c);
};

/// Maps RelayCommand to (power, polarity) and enforces, whatever commands arrive:
/// - power is on only when the polarity already matches the command (never drives the wrong way:
///   a command against the present polarity opens the power relay at once);
/// - the polarity relay changes only on a tick where power is off and has been off ≥ dead_s;
/// - power closes only on a later tick than a polarity change, and ≥ settle_s after it.
/// So a reversal after RelayDrive's dead time costs one extra tick plus settle_s. While Off the
/// polarity relay keeps its state (no needless switching). At construction power is assumed to
/// have been on until the first update, and the polarity relay to have just moved (unknown
/// history after a restart): the first power-on waits settle_s, a first polarity change dead_s.
class PowerPolarityRelays {
 public:
  /// Precondition: PowerPolarityConfig::make(config).ok().
  explicit PowerPolarityRelays(const PowerPolarityConfig& config) : config_(config) {}

  /// The outputs for this tick. A non-finite or backwards `now_s` opens power at once.
  PowerPolarity update(RelayCommand command, double now_s);
  /// Opens power at once; the dead time runs from now_s (from the next update if not finite).
  void halt(double now_s);

  [[nodiscard]] const PowerPolarity& output() const { return output_; }
  [[nodiscard]] const PowerPolarityConfig& config() const { return config_; }

 private:
  void power_off(double now_s);

  PowerPolarityConfig config_;
  PowerPolarity output_;
  std::optional<double> off_since_s_;       ///< empty: set by the next valid update
  std::optional<double> polarity_since_s_;  ///< empty: set by the next valid update
  std::optional<double> last_now_s_;
};

}  // namespace azt::control
