#pragma once

#include <cstdint>
#include <string_view>

#include "azt/util/result.hpp"

namespace azt::control {

// A linear actuator turning an axis (satellite-TV "superjacks", LINAK and similar): the actuator
// is one side of a triangle whose other two sides are fixed lengths, so its length is not
// proportional to the angle. docs/hardware.md ("Linear actuators") has the drawing and a worked
// example (an 18-inch actuator on a 1.2 m dish) that tests/unit/control/actuator_geometry_test.cpp
// checks to 0.01°.
//
//                     B  (moving end, on the dish's arm)
//                    /|
//                 b / |  L (the actuator, pin to pin)
//                  /  |
//                 / φ |
//                O----A  (fixed end, on the mount)
//                   a
//
// O is the axis's pivot, A the actuator's fixed pin at distance a from O, B its moving pin at
// distance b from O. φ is the angle AOB. The law of cosines gives
//     L² = a² + b² − 2ab·cos φ,   φ = acos((a² + b² − L²) / (2ab)),
// and the mount angle θ (elevation for an elevation actuator) is φ − θ0 when extending the
// actuator raises the angle, θ0 − φ when it lowers it. θ0 is a fixed property of the mount: the
// angle AOB at which the axis reads 0°.
//
// dθ/dL = L / (a·b·sin φ) (radians per unit length): the degrees per millimetre (and so per
// pulse of a reed sensor) grow as the actuator and the arm approach a straight line (sin φ → 0),
// so a constant "pulses per degree" is wrong over a long stroke. The stroke must stay clear of
// the straight lines (φ = 0°, 180°) where the triangle collapses and one millimetre is an
// unbounded angle; the configuration refuses a stroke that reaches them.

/// Which way the axis turns when the actuator extends.
enum class ActuatorSense : std::uint8_t {
  ExtendRaises,  ///< θ = φ − θ0: extending turns towards increasing mount angle
  ExtendLowers,  ///< θ = θ0 − φ: extending turns towards decreasing mount angle
};

std::string_view to_string(ActuatorSense sense);

/// +1 when extending raises the angle, −1 when it lowers it: the sign of dθ/dL.
double extension_sign(ActuatorSense sense);

/// The triangle of one actuator axis. Lengths in millimetres, angles in degrees.
struct ActuatorGeometryConfig {
  double pivot_to_fixed_mm = 0.0;   ///< a: the pivot O to the actuator's fixed pin A
  double pivot_to_moving_mm = 0.0;  ///< b: the pivot O to the actuator's moving pin B
  double offset_deg = 0.0;          ///< θ0: the angle AOB at which the mount angle is 0°
  double retracted_mm = 0.0;        ///< L at the actuator's retracted end (pin to pin)
  double extended_mm = 0.0;         ///< L at its extended end: retracted + stroke
  ActuatorSense sense = ActuatorSense::ExtendRaises;

  /// Validates: every number finite, a and b positive, θ0 within ±360°, retracted < extended,
  /// and the whole stroke strictly inside |a − b| .. a + b with φ at least kMinTriangleDeg from
  /// a straight line at both ends. Errors name the field.
  static Result<ActuatorGeometryConfig> make(const ActuatorGeometryConfig& c);
};

/// The smallest angle between the actuator's line and the arm (at either end of the stroke) the
/// configuration accepts: at 5° from a straight line one millimetre is already 11× the degrees it
/// is at right angles, and a pulse count there is too coarse to point with.
inline constexpr double kMinTriangleDeg = 5.0;

/// Length ↔ angle for one actuator. Pure and stateless after construction.
///
/// A length becomes the axis's mount angle through angle_deg() for both sensors that measure it:
/// a pulse count in control::PulseScale (plugged in by PulseAxis, pulse_axis.hpp) and a feedback
/// pot in control::PotInput (pot_calibration.hpp). Each sensor's step in degrees is its
/// millimetres per step times max_deg_per_mm(), the coarse end. Targets outside the angle range
/// are refused with the words of length_mm().
class ActuatorGeometry {
 public:
  /// Precondition: ActuatorGeometryConfig::make(config).ok().
  explicit ActuatorGeometry(const ActuatorGeometryConfig& config);
  static Result<ActuatorGeometry> make(const ActuatorGeometryConfig& config);

  /// The mount angle at actuator length `length_mm`; refused outside the stroke (a reading there
  /// is a sensor or count error, not a place the actuator can be).
  [[nodiscard]] Result<double> angle_deg(double length_mm) const;
  /// The actuator length that puts the axis at `angle_deg`; refused outside the stroke's angles.
  [[nodiscard]] Result<double> length_mm(double angle_deg) const;
  /// dθ/dL in degrees per millimetre at `length_mm` (signed: negative for ExtendLowers). NaN
  /// outside the stroke.
  [[nodiscard]] double deg_per_mm(double length_mm) const;
  /// The largest |dθ/dL| over the stroke: the coarsest end (for a sensor's step in degrees).
  [[nodiscard]] double max_deg_per_mm() const;

  /// The stroke's angle range, min ≤ max whatever the sense.
  [[nodiscard]] double min_angle_deg() const { return min_angle_deg_; }
  [[nodiscard]] double max_angle_deg() const { return max_angle_deg_; }
  [[nodiscard]] const ActuatorGeometryConfig& config() const { return config_; }

 private:
  [[nodiscard]] double phi_deg(double length_mm) const;
  [[nodiscard]] double angle_from_phi(double phi_deg) const;
  [[nodiscard]] double phi_from_angle(double angle_deg) const;

  ActuatorGeometryConfig config_;
  double min_angle_deg_ = 0.0;
  double max_angle_deg_ = 0.0;
};

}  // namespace azt::control
