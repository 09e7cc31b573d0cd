#pragma once
// The offsets of a pointing scan (docs/calibration.md; astronomy-and-eme.md §8): where, relative to
// the source as the ephemeris gives it at each point, the beam is sent to measure the power.
// Offsets are on the sky: cross-elevation (azimuth × cos E) and elevation, in degrees.

#include <cstddef>
#include <string_view>
#include <vector>

#include "azt/calibration/pointing_model.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

enum class ScanKind {
  Cross,      ///< a line in cross-elevation, then one in elevation, through the source
  FivePoint,  ///< the source and four points half a beamwidth off it, and two off-source points
  Raster,     ///< a square grid over the source, row by row (boustrophedon)
};

std::string_view to_string(ScanKind kind);
/// "cross", "five-point" or "raster".
Result<ScanKind> parse_scan_kind(std::string_view text);

struct ScanSpec {
  ScanKind kind = ScanKind::Cross;
  double beamwidth_deg = 1.0;        ///< the expected half-power beamwidth (HPBW)
  double half_span_beams = 2.0;      ///< cross and raster: ± this many beamwidths
  std::size_t points_per_line = 21;  ///< cross: per line; raster: per side (odd: one on the source)
  double reference_beams = 4.0;      ///< five-point: the off-source points at ± this in xel

  static constexpr double kMaxBeamwidthDeg = 30.0;
  static constexpr std::size_t kMaxPointsPerLine = 101;
};

struct ScanPoint {
  SkyOffset offset;
  bool reference = false;  ///< an off-source point for the baseline (five-point)
};

/// The points in the order they are measured. Fails, naming the field, on a beamwidth outside
/// (0, 30]°, a span outside (0, 10] beamwidths, points per line outside 5–101 or even, a
/// reference closer than 2.5 beamwidths.
Result<std::vector<ScanPoint>> plan_scan(const ScanSpec& spec);

}  // namespace azt::calibration
