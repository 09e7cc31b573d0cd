#include "azt/control/corrections.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "azt/control/axis_geometry.hpp"

namespace azt::control {
namespace {

/// Hundredths of a degree per degree: the seed's 0.01° step.
constexpr double kStepsPerDeg = 100.0;

/// Adds `steps` to `total`, saturating at ±kMaxSteps. Returns false when saturation cut it short.
bool add_saturated(std::int32_t& total, std::int32_t steps) {
  const std::int64_t wanted = std::int64_t{total} + std::int64_t{steps};
  const std::int64_t limit = UserCorrections::kMaxSteps;
  const std::int64_t kept = std::clamp(wanted, -limit, limit);
  total = static_cast<std::int32_t>(kept);
  return kept == wanted;
}

Result<std::int32_t> steps_from_deg(double deg, const char* axis) {
  const double max_deg = UserCorrections::kMaxSteps / kStepsPerDeg;
  // Half a step of slack so that a stored "10.00" that parsed as 10.000000000000002 still loads.
  if (!std::isfinite(deg) || std::fabs(deg) > max_deg + 0.5 / kStepsPerDeg) {
    return fail(std::string(axis) + " user correction must be finite and within ±10.00 degrees");
  }
  return static_cast<std::int32_t>(std::lround(deg * kStepsPerDeg));
}

Result<double> checked_tilt(double deg) {
  if (!std::isfinite(deg) || std::fabs(deg) > TiltTable::kMaxCorrectionDeg) {
    return fail("tilt correction must be finite and within ±5 degrees");
  }
  return deg;
}

}  // namespace

double normalize_az_deg(double az_deg) { return wrap_360(az_deg); }

double normalize_el_deg(double el_deg) {
  // Values already in range are returned untouched, so a corrected 0.00 stays exactly 0.00.
  if (el_deg >= -90.0 && el_deg < 270.0) return el_deg;
  return wrap_360(el_deg + 90.0) - 90.0;
}

Result<AxisOffsets> AxisOffsets::make(double az_deg, double el_deg) {
  if (!std::isfinite(az_deg) || std::fabs(az_deg) > kMaxAzDeg) {
    return fail("azimuth offset must be finite and within ±360 degrees");
  }
  if (!std::isfinite(el_deg) || std::fabs(el_deg) > kMaxElDeg) {
    return fail("elevation offset must be finite and within ±180 degrees");
  }
  return AxisOffsets{az_deg, el_deg};
}

Result<UserCorrections> UserCorrections::from_deg(double az_deg, double el_deg) {
  const auto az = steps_from_deg(az_deg, "azimuth");
  if (!az) return az.error();
  const auto el = steps_from_deg(el_deg, "elevation");
  if (!el) return el.error();
  UserCorrections u;
  u.az_steps_ = std::clamp(*az, -kMaxSteps, kMaxSteps);
  u.el_steps_ = std::clamp(*el, -kMaxSteps, kMaxSteps);
  return u;
}

bool UserCorrections::nudge_az(std::int32_t steps) { return add_saturated(az_steps_, steps); }
bool UserCorrections::nudge_el(std::int32_t steps) { return add_saturated(el_steps_, steps); }

void UserCorrections::reset() {
  az_steps_ = 0;
  el_steps_ = 0;
}

// One division of an exact integer: the result is the double nearest the decimal total, the same
// double the literal (e.g. 0.07) denotes. Summing 0.01 repeatedly would not be.
double UserCorrections::az_deg() const { return az_steps_ / kStepsPerDeg; }
double UserCorrections::el_deg() const { return el_steps_ / kStepsPerDeg; }

Result<TiltTable> TiltTable::make(const std::vector<double>& entries_deg) {
  if (entries_deg.size() != kEntries) {
    return fail("tilt table needs exactly 60 entries (one every 6 degrees of azimuth), got " +
                std::to_string(entries_deg.size()));
  }
  TiltTable table;
  for (std::size_t i = 0; i < kEntries; ++i) {
    const auto entry = checked_tilt(entries_deg[i]);
    if (!entry) return fail("tilt entry " + std::to_string(i) + ": " + entry.error().message);
    table.entries_deg_[i] = *entry;
  }
  return table;
}

Result<TiltTable> TiltTable::with_entry(std::size_t index, double correction_deg) const {
  if (index >= kEntries) return fail("tilt entry index must be 0 to 59");
  const auto entry = checked_tilt(correction_deg);
  if (!entry) return entry.error();
  TiltTable copy = *this;
  copy.entries_deg_[index] = *entry;
  return copy;
}

double TiltTable::correction_el_deg(double az_deg) const {
  const double az = wrap_360(az_deg);
  if (!std::isfinite(az)) return std::numeric_limits<double>::quiet_NaN();
  const double position = az / kSpacingDeg;  // 0 ≤ position < 60
  const std::size_t i = std::min(static_cast<std::size_t>(position), kEntries - 1);
  const std::size_t next = (i + 1) % kEntries;  // 354° interpolates towards 000° (= 360°)
  const double fraction = position - static_cast<double>(i);
  return entries_deg_[i] + (entries_deg_[next] - entries_deg_[i]) * fraction;
}

CorrectedPosition apply_corrections(double raw_az_deg, double raw_el_deg,
                                    const PositionCorrections& corrections) {
  const AzEl mount{normalize_az_deg(raw_az_deg + corrections.offsets.az_deg),
                   normalize_el_deg(raw_el_deg + corrections.offsets.el_deg)};
  const AzEl beam = calibration::corrected_reading(mount, corrections.model);
  const double az = normalize_az_deg(beam.az_deg - corrections.user.az_deg());
  const double el = beam.el_deg - corrections.user.el_deg();
  const double tilt = corrections.tilt.correction_el_deg(az);
  return CorrectedPosition{az, normalize_el_deg(el + tilt), tilt, beam.az_deg - mount.az_deg,
                           beam.el_deg - mount.el_deg};
}

}  // namespace azt::control
