#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "azt/control/actuator_geometry.hpp"
#include "azt/control/homing.hpp"
#include "azt/control/pulse_counter.hpp"
#include "azt/control/pulse_scale.hpp"
#include "azt/ports/pulse_input.hpp"
#include "azt/util/result.hpp"

namespace azt::control {

// A pulse-counted axis sensor (docs/hardware.md, "Pulse sensors and homing"): the counter, the
// homing and the scale of one axis wired the way their plug-in points say, so DrivenAxis holds one
// piece rather than three. The edges arrive through ports::PulseInput; the count becomes an angle
// only once homed. Before that the axis has a position relative to where it started (counts times
// the scale at the home point), which the supervisor watches during the homing moves (a stale
// count stops them as a stale encoder would) but which no target is ever driven to.

struct PulseAxisConfig {
  PulseCounterConfig counter;
  HomingConfig homing;
  PulseScaleConfig scale;
  /// The actuator's triangle: for a scale in millimetres only.
  std::optional<ActuatorGeometryConfig> geometry;
  /// Home when the station starts; false: the axis waits for the operator's command.
  bool home_at_start = true;
};

class PulseAxis {
 public:
  /// Validates each part (their own make()); errors name the part.
  static Result<PulseAxis> make(const PulseAxisConfig& config);

  /// Begins (or restarts) homing at `now_s`; `home_closed` is the switch's level now.
  void start_homing(double now_s, bool home_closed);
  /// This tick's edges, oldest first: pulses to the counter, the home switch to the homing with
  /// the count at its time (each pulse before it has been counted).
  void on_edges(std::span<const ports::PulseEdge> edges);
  /// While homing is active: its duty now (it checks its timeouts and travel here); nullopt
  /// otherwise (the axis tracks or holds).
  std::optional<double> homing_duty(double now_s);
  /// The duty the motor really gets from `now_s` on (after every limit, brake and trip): the
  /// single channel's direction.
  void set_drive(double duty, double now_s);
  /// Stops a homing in progress (a fault, a STOP): NotHomed with `reason`.
  void abort(std::string_view reason) { homing_.abort(reason); }
  /// The operator's clear: a failed homing or a lost position goes back to NotHomed.
  void reset() { homing_.reset(); }

  /// Homed: the mount angle of the count (refused outside an actuator's stroke: a count error).
  /// Not homed: `origin_deg` plus the count at the home point's scale (unreferenced).
  [[nodiscard]] Result<double> position_deg(double origin_deg) const;
  /// The count's worth in degrees at the home point (for the unreferenced position).
  [[nodiscard]] double nominal_deg_per_count() const { return nominal_deg_per_count_; }
  [[nodiscard]] bool homed() const { return homing_.homed(); }
  [[nodiscard]] bool homing_active() const { return homing_.active(); }
  [[nodiscard]] bool position_lost() const { return homing_.state() == HomingState::PositionLost; }
  /// Homing's words while targets are refused; empty once homed.
  [[nodiscard]] std::optional<std::string> why_not_homed() const { return homing_.why_not_homed(); }

  [[nodiscard]] const PulseCounter& counter() const { return counter_; }
  [[nodiscard]] const Homing& homing() const { return homing_; }
  [[nodiscard]] const PulseScale& scale() const { return scale_; }
  [[nodiscard]] bool home_at_start() const { return home_at_start_; }

 private:
  PulseAxis(const PulseCounter& counter, const Homing& homing, const PulseScale& scale,
            bool home_at_start);

  PulseCounter counter_;
  Homing homing_;
  PulseScale scale_;
  bool home_at_start_;
  double nominal_deg_per_count_;
};

}  // namespace azt::control
