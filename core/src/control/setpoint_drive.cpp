#include "azt/control/setpoint_drive.hpp"

#include <algorithm>
#include <cmath>

namespace azt::control {
namespace {

constexpr double kMaxWiper = 255.0;  // MCP41010: 256 taps, codes 0..255

bool valid_wiper(double w) { return std::isfinite(w) && w >= 0.0 && w <= kMaxWiper; }

}  // namespace

Result<SetpointCalibration> SetpointCalibration::make(double wiper_a, double deg_a, double wiper_b,
                                                      double deg_b) {
  if (!valid_wiper(wiper_a) || !valid_wiper(wiper_b)) return fail("wiper codes must be 0 to 255");
  if (!std::isfinite(deg_a) || !std::isfinite(deg_b)) return fail("angles must be finite");
  if (wiper_a == wiper_b) return fail("the two calibration points need distinct wiper codes");
  if (deg_a == deg_b) return fail("the two calibration points need distinct angles");
  return SetpointCalibration{wiper_a, deg_a, wiper_b, deg_b};
}

double SetpointCalibration::wiper_from_deg(double deg) const {
  // Multiply before dividing: whole-number calibrations (0 → 0, 450° → 255) then give exact
  // codes at their end points, so the ends are not reported as clamped by a rounding error.
  return wiper_a + (deg - deg_a) * (wiper_b - wiper_a) / (deg_b - deg_a);
}

double SetpointCalibration::deg_from_wiper(double wiper) const {
  return deg_a + (wiper - wiper_a) * (deg_b - deg_a) / (wiper_b - wiper_a);
}

double SetpointCalibration::step_deg() const {
  return std::fabs(deg_b - deg_a) / std::fabs(wiper_b - wiper_a);
}

SetpointUpdate SetpointDrive::update(double target_deg) {
  SetpointUpdate out;
  if (!std::isfinite(target_deg)) {
    out.status = SetpointStatus::NotFinite;
    return out;
  }
  const double exact = calibration_.wiper_from_deg(target_deg);
  out.status = exact < 0.0 || exact > kMaxWiper ? SetpointStatus::Clamped : SetpointStatus::InRange;
  // Nearest code, halves away from zero (std::round); the clamp also tames an overflow to ±inf.
  out.wiper = static_cast<std::uint8_t>(std::clamp(std::round(exact), 0.0, kMaxWiper));
  if (last_sent_ != out.wiper) {
    out.send = out.wiper;
    last_sent_ = out.wiper;
  }
  return out;
}

}  // namespace azt::control
