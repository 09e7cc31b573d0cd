#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::control {

// Incremental position sensors: a reed switch or a Hall sensor giving one pulse per step (the
// satellite-TV actuators' reed, LINAK's Hall option), or a quadrature pair (two channels 90°
// apart). The counter turns their edges, each with the timestamp its input reported (libgpiod's
// edge events carry one), into a signed count; control::PulseScale turns the count into an
// angle and control::Homing says where count zero is.
//
// Forward is towards increasing mount angle (the sign of a positive duty, axis_controller.hpp):
// the count rises while the axis moves forward.

/// How the sensor is wired.
enum class PulseInputKind : std::uint8_t {
  /// One channel: a pulse says "one step", not which way. The direction is the drive's, as the
  /// controller commanded it; after the drive stops, pulses keep counting in the last direction
  /// (the motor coasts on), as K3NG's rotator controller does by default
  /// (k3ng_rotator_controller.ino, its pulse input interrupts; K3NG's
  /// OPTION_PULSE_IGNORE_AMBIGUOUS_PULSES, which drops them instead, would lose the coast).
  /// Consequence: a reversal must wait until the motor has stopped (the relay drive's and the
  /// H-bridge's dead times), or the coast of the old direction counts as the new one.
  SingleChannel,
  /// Two channels in quadrature: the direction is the phase between them, every edge of either
  /// channel is one count (×4 decoding), whatever the drive does.
  Quadrature,
};

std::string_view to_string(PulseInputKind kind);

struct PulseCounterConfig {
  PulseInputKind kind = PulseInputKind::SingleChannel;
  /// Single channel only: a pulse less than this after the last accepted one is contact bounce
  /// (or motor noise on the line: AMSAT-BB 2008-April/010753 on motor hash corrupting counts)
  /// and is dropped. Default 10 ms: LINAK's Hall output keeps pulse and pause at least 10 ms
  /// each (LINAK TECHLINE LA35 user manual, its Hall output), so real pulses are ≥ 20 ms apart;
  /// choose it below the shortest real pulse period at full speed. K3NG's elevation default is 500
  /// ms (EL_POSITION_PULSE_DEBOUNCE) for much slower pulse trains. Quadrature is not debounced: a
  /// bouncing edge counts up and down again and nets zero, which is why quadrature is used, and a
  /// filter that drops edges would leave the decoder's state unlike the lines'.
  double min_spacing_s = 0.010;
  /// Quadrature only: count the other way (channels swapped in the wiring).
  bool reversed = false;

  /// Validates: min_spacing_s in [0, 1] s.
  static Result<PulseCounterConfig> make(const PulseCounterConfig& c);
};

/// Which way the drive is turning the motor this tick.
enum class DriveDirection : std::uint8_t { Stopped, Forward, Reverse };

/// The two channels of a quadrature sensor.
enum class QuadratureChannel : std::uint8_t { A, B };

/// Counts one axis's pulses. Pure: every edge carries its own timestamp in seconds of the same
/// monotonic clock as the ticks (libgpiod's event timestamps).
///
/// Plugged in by PulseAxis (pulse_axis.hpp), which DrivenAxis runs; each tick in this order:
///  1. every edge event that arrived, in timestamp order: on_pulse() (single channel) or
///     on_quadrature_edge(), interleaved with the home switch's edges to Homing::on_switch() so
///     the count at a switch edge is the count at its time;
///  2. set_drive() with the direction the drive will turn this tick (from the duty after every
///     limit, brake and trip has had its say: the direction the motor really gets);
///  3. the count to Homing and PulseScale for the position.
/// Edges timestamped before the last set_drive() (an event read a tick late) are counted in the
/// direction that was in force at their time.
class PulseCounter {
 public:
  /// Precondition: PulseCounterConfig::make(config).ok().
  explicit PulseCounter(const PulseCounterConfig& config) : config_(config) {}

  /// The drive's direction from `now_s` on. Stopped keeps the last moving direction for the
  /// coast (single channel).
  void set_drive(DriveDirection direction, double now_s);

  /// Single channel: one pulse at `at_s`. Ignored (counted as an error) for a quadrature input.
  void on_pulse(double at_s);
  /// Quadrature: `channel` went to `high` at `at_s`. Ignored (an error) for a single channel.
  void on_quadrature_edge(QuadratureChannel channel, bool high, double at_s);

  /// Forward counts minus reverse counts since construction (or the last reset_count()).
  [[nodiscard]] std::int64_t count() const { return count_; }
  /// Pulses dropped as bounce (closer than min_spacing_s to the last accepted one).
  [[nodiscard]] std::uint64_t bounces() const { return bounces_; }
  /// Pulses that came before the drive ever moved: no direction to count them in (a single
  /// channel at start-up, or the axis pushed by hand or wind). Not counted.
  [[nodiscard]] std::uint64_t ambiguous() const { return ambiguous_; }
  /// Edges that cannot be: a quadrature channel "changing" to the level it already had (an edge
  /// was lost in between, so the count may be one or two off), a timestamp earlier than the
  /// last edge's or not finite, an edge of the wrong kind for the input. Not counted.
  [[nodiscard]] std::uint64_t errors() const { return errors_; }
  /// The timestamp of the last counted edge (for a stale or stall check); empty before one.
  [[nodiscard]] std::optional<double> last_edge_s() const { return last_edge_s_; }
  [[nodiscard]] const PulseCounterConfig& config() const { return config_; }

  /// Sets the count (a test fixture, or an operator entering a known position); Homing keeps
  /// its own reference instead and never calls this.
  void reset_count(std::int64_t count) { count_ = count; }
  /// Quadrature: the levels the lines have now (read once at start-up, before any edge).
  void set_quadrature_levels(bool a_high, bool b_high);

 private:
  [[nodiscard]] bool accept_time(double at_s);
  [[nodiscard]] DriveDirection direction_at(double at_s) const;

  PulseCounterConfig config_;
  std::int64_t count_ = 0;
  std::uint64_t bounces_ = 0;
  std::uint64_t ambiguous_ = 0;
  std::uint64_t errors_ = 0;
  std::optional<double> last_edge_s_;
  std::optional<double> last_seen_s_;  ///< of any edge with a valid time, counted or not
  std::optional<double> last_accepted_pulse_s_;
  // The moving direction in force since `direction_since_s_`, and the one before it (Stopped
  // only before the first move: set_drive(Stopped) keeps the coast's direction).
  DriveDirection direction_ = DriveDirection::Stopped;
  DriveDirection previous_direction_ = DriveDirection::Stopped;
  double direction_since_s_ = 0.0;
  bool a_high_ = false;
  bool b_high_ = false;
};

}  // namespace azt::control
