#include "azt/control/actuator_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string>

#include "azt/util/format_number.hpp"

namespace azt::control {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
// Rounding slack at the ends of the stroke: a length computed from an end angle may come back a
// few ulps outside it, and must not be refused for that.
constexpr double kEndSlack = 1e-9;

bool all_finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// φ in degrees for a triangle with sides a, b (at O) and l opposite O; NaN when no triangle.
double law_of_cosines_deg(double a, double b, double l) {
  const double cos_phi = (a * a + b * b - l * l) / (2.0 * a * b);
  if (!(cos_phi >= -1.0 && cos_phi <= 1.0)) return std::numeric_limits<double>::quiet_NaN();
  return std::acos(cos_phi) * kDegPerRad;
}

Result<bool> check_stroke(const ActuatorGeometryConfig& c) {
  const double a = c.pivot_to_fixed_mm;
  const double b = c.pivot_to_moving_mm;
  if (c.retracted_mm <= std::fabs(a - b)) {
    return fail("retracted_mm must be above |pivot_to_fixed_mm - pivot_to_moving_mm| = " +
                format_number(std::fabs(a - b)) + " mm, or the triangle closes");
  }
  if (c.extended_mm >= a + b) {
    return fail("extended_mm must be below pivot_to_fixed_mm + pivot_to_moving_mm = " +
                format_number(a + b) + " mm, or the triangle closes");
  }
  const double phi_min = law_of_cosines_deg(a, b, c.retracted_mm);
  const double phi_max = law_of_cosines_deg(a, b, c.extended_mm);
  if (phi_min < kMinTriangleDeg) {
    return fail("retracted_mm leaves the actuator " + format_fixed(phi_min, 2) +
                " deg from the line of the arm; at least " + format_number(kMinTriangleDeg) +
                " deg are needed");
  }
  if (phi_max > 180.0 - kMinTriangleDeg) {
    return fail("extended_mm leaves the actuator " + format_fixed(180.0 - phi_max, 2) +
                " deg from the line of the arm; at least " + format_number(kMinTriangleDeg) +
                " deg are needed");
  }
  return true;
}

}  // namespace

std::string_view to_string(ActuatorSense sense) {
  switch (sense) {
    case ActuatorSense::ExtendRaises:
      return "extend raises";
    case ActuatorSense::ExtendLowers:
      return "extend lowers";
  }
  return "unknown";
}

double extension_sign(ActuatorSense sense) {
  switch (sense) {
    case ActuatorSense::ExtendRaises:
      return 1.0;
    case ActuatorSense::ExtendLowers:
      return -1.0;
  }
  return 1.0;
}

Result<ActuatorGeometryConfig> ActuatorGeometryConfig::make(const ActuatorGeometryConfig& c) {
  if (!std::isfinite(c.pivot_to_fixed_mm) || c.pivot_to_fixed_mm <= 0.0) {
    return fail("pivot_to_fixed_mm must be finite and positive");
  }
  if (!std::isfinite(c.pivot_to_moving_mm) || c.pivot_to_moving_mm <= 0.0) {
    return fail("pivot_to_moving_mm must be finite and positive");
  }
  if (!std::isfinite(c.offset_deg) || std::fabs(c.offset_deg) > 360.0) {
    return fail("offset_deg must be within -360 to 360 deg");
  }
  if (!all_finite({c.retracted_mm, c.extended_mm})) {
    return fail("retracted_mm and extended_mm must be finite");
  }
  if (c.retracted_mm >= c.extended_mm) return fail("retracted_mm must be below extended_mm");
  if (const auto stroke = check_stroke(c); !stroke) return stroke.error();
  return c;
}

ActuatorGeometry::ActuatorGeometry(const ActuatorGeometryConfig& config) : config_(config) {
  const double at_retracted = angle_from_phi(phi_deg(config.retracted_mm));
  const double at_extended = angle_from_phi(phi_deg(config.extended_mm));
  min_angle_deg_ = std::min(at_retracted, at_extended);
  max_angle_deg_ = std::max(at_retracted, at_extended);
}

Result<ActuatorGeometry> ActuatorGeometry::make(const ActuatorGeometryConfig& config) {
  const auto ok = ActuatorGeometryConfig::make(config);
  if (!ok) return ok.error();
  return ActuatorGeometry(config);
}

double ActuatorGeometry::phi_deg(double length_mm) const {
  return law_of_cosines_deg(config_.pivot_to_fixed_mm, config_.pivot_to_moving_mm, length_mm);
}

double ActuatorGeometry::angle_from_phi(double phi_deg) const {
  switch (config_.sense) {
    case ActuatorSense::ExtendRaises:
      return phi_deg - config_.offset_deg;
    case ActuatorSense::ExtendLowers:
      return config_.offset_deg - phi_deg;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double ActuatorGeometry::phi_from_angle(double angle_deg) const {
  switch (config_.sense) {
    case ActuatorSense::ExtendRaises:
      return angle_deg + config_.offset_deg;
    case ActuatorSense::ExtendLowers:
      return config_.offset_deg - angle_deg;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

Result<double> ActuatorGeometry::angle_deg(double length_mm) const {
  const double lo = config_.retracted_mm;
  const double hi = config_.extended_mm;
  if (!std::isfinite(length_mm) || length_mm < lo - kEndSlack || length_mm > hi + kEndSlack) {
    return fail("actuator length " + format_fixed(length_mm, 1) + " mm is outside its stroke " +
                format_number(lo) + " to " + format_number(hi) + " mm");
  }
  return angle_from_phi(phi_deg(std::clamp(length_mm, lo, hi)));
}

Result<double> ActuatorGeometry::length_mm(double angle_deg) const {
  if (!std::isfinite(angle_deg) || angle_deg < min_angle_deg_ - kEndSlack ||
      angle_deg > max_angle_deg_ + kEndSlack) {
    return fail("angle " + format_fixed(angle_deg, 2) + " deg is outside the actuator's range " +
                format_fixed(min_angle_deg_, 2) + " to " + format_fixed(max_angle_deg_, 2) +
                " deg");
  }
  const double a = config_.pivot_to_fixed_mm;
  const double b = config_.pivot_to_moving_mm;
  const double cos_phi = std::cos(phi_from_angle(angle_deg) / kDegPerRad);
  const double length = std::sqrt(a * a + b * b - 2.0 * a * b * cos_phi);
  return std::clamp(length, config_.retracted_mm, config_.extended_mm);
}

double ActuatorGeometry::deg_per_mm(double length_mm) const {
  if (!(length_mm >= config_.retracted_mm - kEndSlack &&
        length_mm <= config_.extended_mm + kEndSlack)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  const double sin_phi = std::sin(phi_deg(length_mm) / kDegPerRad);
  const double rad_per_mm =
      length_mm / (config_.pivot_to_fixed_mm * config_.pivot_to_moving_mm * sin_phi);
  return extension_sign(config_.sense) * rad_per_mm * kDegPerRad;
}

double ActuatorGeometry::max_deg_per_mm() const {
  // |dθ/dL| ∝ L / sin φ. Its derivative in φ has the sign of ab·sin²φ − L²·cos φ, which with
  // c = cos φ is ab·(c − a/b)(c − b/a): negative only while c > min(a, b)/max(a, b). So the
  // degrees per millimetre fall until the actuator stands at right angles to the shorter side
  // and rise after it (a single minimum): the largest is at one end of the stroke.
  return std::max(std::fabs(deg_per_mm(config_.retracted_mm)),
                  std::fabs(deg_per_mm(config_.extended_mm)));
}

}  // namespace azt::control
