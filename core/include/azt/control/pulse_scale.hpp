#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "azt/control/actuator_geometry.hpp"
#include "azt/util/result.hpp"

namespace azt::control {

// Counts become an angle: position = home position + counts from home / scale. On a rotator
// (a reed on the ring gear, a Hall sensor on the motor) the scale is counts per degree of the
// axis; on a linear actuator it is counts per millimetre of
// actuator length, and the length becomes the angle through the actuator's triangle
// (actuator_geometry.hpp): degrees per count then vary along the stroke.

/// What one count measures.
enum class PulseUnit : std::uint8_t {
  Degrees,      ///< counts per degree of the axis
  Millimetres,  ///< counts per millimetre of actuator length, through an ActuatorGeometry
};

std::string_view to_string(PulseUnit unit);

struct PulseScaleConfig {
  PulseUnit unit = PulseUnit::Degrees;
  /// Counts per degree or per millimetre, positive. For a reed counted on one edge, the
  /// actuator's pulses per mm (LINAK LA12 with a 4-pole magnet: 1 pulse per mm on a 4 mm
  /// spindle pitch, LINAK's LA12 connection diagram); for ×4 quadrature, four times the lines.
  double counts_per_unit = 1.0;
  /// The axis angle (degrees) or the actuator length (millimetres) where the home switch closes.
  double home_value = 0.0;
};

/// Turns a count from the home switch into a mount angle. Counts rise in the forward direction
/// (increasing angle), so on an actuator whose extension lowers the angle the length falls as the
/// count rises.
///
/// Plugged in by PulseAxis (pulse_axis.hpp): position_deg = angle_deg(homing.counts_from_home
/// (counter.count())) each tick once homed; its refusal (a count outside the stroke) is a sensor
/// fault that stops the axis, as a pot outside its guards is. The supervisor's step size is
/// max_deg_per_count().
class PulseScale {
 public:
  /// Validates: counts_per_unit finite in (0, 1e6], home_value finite; Millimetres needs the
  /// geometry and a home length inside its stroke, Degrees refuses one (it would be unused).
  /// Errors name the field.
  static Result<PulseScale> make(const PulseScaleConfig& config,
                                 std::optional<ActuatorGeometry> geometry = std::nullopt);

  /// The mount angle `counts_from_home` counts from the home switch; refused where the actuator
  /// cannot be (outside its stroke).
  [[nodiscard]] Result<double> angle_deg(std::int64_t counts_from_home) const;
  /// The (fractional) count from home at `angle_deg`; refused outside the actuator's range.
  [[nodiscard]] Result<double> counts_at(double angle_deg) const;
  /// Degrees per count at `counts_from_home` (positive; NaN outside the stroke).
  [[nodiscard]] double deg_per_count(std::int64_t counts_from_home) const;
  /// The coarsest count anywhere on the axis: the supervisor's and the controller's step.
  [[nodiscard]] double max_deg_per_count() const;

  [[nodiscard]] const PulseScaleConfig& config() const { return config_; }

 private:
  PulseScale(const PulseScaleConfig& config, std::optional<ActuatorGeometry> geometry)
      : config_(config), geometry_(geometry) {}
  [[nodiscard]] double length_mm(std::int64_t counts_from_home) const;
  [[nodiscard]] double length_sign() const;

  PulseScaleConfig config_;
  std::optional<ActuatorGeometry> geometry_;
};

}  // namespace azt::control
