#include "azt/proto/fodtrack.hpp"

#include <algorithm>
#include <cmath>

namespace azt::proto {

Result<FodtrackScale> FodtrackScale::make(double az_full_scale_deg, double el_full_scale_deg) {
  const auto ok = [](double v) { return std::isfinite(v) && v >= 1.0 && v <= 720.0; };
  if (!ok(az_full_scale_deg)) return fail("FODTRACK azimuth full scale: 1 to 720 degrees");
  if (!ok(el_full_scale_deg)) return fail("FODTRACK elevation full scale: 1 to 720 degrees");
  return FodtrackScale{az_full_scale_deg, el_full_scale_deg};
}

std::optional<FodtrackLatch> FodtrackDecoder::feed(const ParallelSample& sample) {
  const bool rising = sample.strobe && !strobe_;
  strobe_ = sample.strobe;
  if (!rising) return std::nullopt;
  FodtrackLatch latch;
  latch.azimuth = sample.autofeed;
  latch.raw = sample.data;
  const double full = latch.azimuth ? scale_.az_full_scale_deg : scale_.el_full_scale_deg;
  latch.angle_deg = static_cast<double>(sample.data) / 255.0 * full;
  (latch.azimuth ? az_deg_ : el_deg_) = latch.angle_deg;
  return latch;
}

std::uint8_t FodtrackDecoder::encode(double angle_deg, double full_scale_deg) {
  if (!std::isfinite(angle_deg) || !(full_scale_deg > 0.0)) return 0;
  const double v = std::clamp(angle_deg / full_scale_deg * 255.0, 0.0, 255.0);
  return static_cast<std::uint8_t>(v);  // truncated, as the programs do
}

}  // namespace azt::proto
