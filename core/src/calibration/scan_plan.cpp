#include "azt/calibration/scan_plan.hpp"

#include <cmath>
#include <string>

namespace azt::calibration {
namespace {

Result<bool> check(const ScanSpec& s) {
  if (!(s.beamwidth_deg > 0.0 && s.beamwidth_deg <= ScanSpec::kMaxBeamwidthDeg)) {
    return fail("beamwidth_deg must be in (0, 30]");
  }
  if (s.kind == ScanKind::FivePoint) {
    if (!(s.reference_beams >= 2.5 && s.reference_beams <= 10.0)) {
      return fail("reference_beams must be in [2.5, 10]");
    }
    return true;
  }
  if (!(s.half_span_beams > 0.0 && s.half_span_beams <= 10.0)) {
    return fail("half_span_beams must be in (0, 10]");
  }
  if (s.points_per_line < 5 || s.points_per_line > ScanSpec::kMaxPointsPerLine ||
      s.points_per_line % 2 == 0) {
    return fail("points_per_line must be odd, 5 to 101");
  }
  return true;
}

/// Evenly spaced from −half to +half, `n` points.
std::vector<double> line(double half_deg, std::size_t n) {
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = -half_deg + 2.0 * half_deg * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  return out;
}

std::vector<ScanPoint> cross(const ScanSpec& s) {
  std::vector<ScanPoint> out;
  for (const double x : line(s.half_span_beams * s.beamwidth_deg, s.points_per_line)) {
    out.push_back({{x, 0.0}, false});
  }
  for (const double y : line(s.half_span_beams * s.beamwidth_deg, s.points_per_line)) {
    out.push_back({{0.0, y}, false});
  }
  return out;
}

std::vector<ScanPoint> five_point(const ScanSpec& s) {
  const double h = 0.5 * s.beamwidth_deg, r = s.reference_beams * s.beamwidth_deg;
  return {{{-r, 0.0}, true},  {{0.0, 0.0}, false}, {{-h, 0.0}, false}, {{h, 0.0}, false},
          {{0.0, -h}, false}, {{0.0, h}, false},   {{r, 0.0}, true}};
}

std::vector<ScanPoint> raster(const ScanSpec& s) {
  const std::vector<double> axis = line(s.half_span_beams * s.beamwidth_deg, s.points_per_line);
  std::vector<ScanPoint> out;
  for (std::size_t row = 0; row < axis.size(); ++row) {
    for (std::size_t i = 0; i < axis.size(); ++i) {
      const std::size_t col = row % 2 == 0 ? i : axis.size() - 1 - i;  // no fly-back between rows
      out.push_back({{axis[col], axis[row]}, false});
    }
  }
  return out;
}

}  // namespace

std::string_view to_string(ScanKind kind) {
  switch (kind) {
    case ScanKind::Cross:
      return "cross";
    case ScanKind::FivePoint:
      return "five-point";
    case ScanKind::Raster:
      return "raster";
  }
  return "cross";
}

Result<ScanKind> parse_scan_kind(std::string_view text) {
  for (const ScanKind k : {ScanKind::Cross, ScanKind::FivePoint, ScanKind::Raster}) {
    if (text == to_string(k)) return k;
  }
  return fail("scan must be cross, five-point or raster");
}

Result<std::vector<ScanPoint>> plan_scan(const ScanSpec& spec) {
  if (auto ok = check(spec); !ok) return ok.error();
  switch (spec.kind) {
    case ScanKind::Cross:
      return cross(spec);
    case ScanKind::FivePoint:
      return five_point(spec);
    case ScanKind::Raster:
      return raster(spec);
  }
  return cross(spec);
}

}  // namespace azt::calibration
