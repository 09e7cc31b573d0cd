#include "azt/control/pulse_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "azt/util/format_number.hpp"

namespace azt::control {
namespace {

// More counts per unit than this is a typing error (a 16-bit encoder per degree is ~180).
constexpr double kMaxCountsPerUnit = 1e6;

}  // namespace

std::string_view to_string(PulseUnit unit) {
  switch (unit) {
    case PulseUnit::Degrees:
      return "degrees";
    case PulseUnit::Millimetres:
      return "millimetres";
  }
  return "unknown";
}

Result<PulseScale> PulseScale::make(const PulseScaleConfig& config,
                                    std::optional<ActuatorGeometry> geometry) {
  if (!std::isfinite(config.counts_per_unit) || config.counts_per_unit <= 0.0 ||
      config.counts_per_unit > kMaxCountsPerUnit) {
    return fail("counts_per_unit must be above 0 and at most 1e6");
  }
  if (!std::isfinite(config.home_value)) return fail("home_value must be finite");
  switch (config.unit) {
    case PulseUnit::Degrees:
      if (geometry) return fail("an actuator geometry needs counts per millimetre, not degrees");
      break;
    case PulseUnit::Millimetres: {
      if (!geometry) return fail("counts per millimetre need the actuator geometry");
      const auto& g = geometry->config();
      if (config.home_value < g.retracted_mm || config.home_value > g.extended_mm) {
        return fail("home_value " + format_number(config.home_value) +
                    " mm is outside the actuator's stroke " + format_number(g.retracted_mm) +
                    " to " + format_number(g.extended_mm) + " mm");
      }
      break;
    }
  }
  return PulseScale(config, geometry);
}

double PulseScale::length_sign() const { return extension_sign(geometry_->config().sense); }

double PulseScale::length_mm(std::int64_t counts_from_home) const {
  return config_.home_value +
         length_sign() * static_cast<double>(counts_from_home) / config_.counts_per_unit;
}

Result<double> PulseScale::angle_deg(std::int64_t counts_from_home) const {
  const double units = static_cast<double>(counts_from_home) / config_.counts_per_unit;
  if (!geometry_) return config_.home_value + units;
  auto angle = geometry_->angle_deg(length_mm(counts_from_home));
  if (!angle) {
    return fail("count " + std::to_string(counts_from_home) +
                " from home: " + angle.error().message);
  }
  return angle;
}

Result<double> PulseScale::counts_at(double angle_deg) const {
  if (!geometry_) {
    if (!std::isfinite(angle_deg)) return fail("angle must be finite");
    return (angle_deg - config_.home_value) * config_.counts_per_unit;
  }
  const auto length = geometry_->length_mm(angle_deg);
  if (!length) return length.error();
  return (*length - config_.home_value) * length_sign() * config_.counts_per_unit;
}

double PulseScale::deg_per_count(std::int64_t counts_from_home) const {
  if (!geometry_) return 1.0 / config_.counts_per_unit;
  return std::fabs(geometry_->deg_per_mm(length_mm(counts_from_home))) / config_.counts_per_unit;
}

double PulseScale::max_deg_per_count() const {
  if (!geometry_) return 1.0 / config_.counts_per_unit;
  return geometry_->max_deg_per_mm() / config_.counts_per_unit;
}

}  // namespace azt::control
