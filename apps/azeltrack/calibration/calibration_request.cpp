#include "calibration/calibration_request.hpp"

#include <cmath>
#include <optional>

#include "azt/calibration/scan_plan.hpp"

namespace azt::app {
namespace {

using nlohmann::json;

/// Thrown inside the reader, caught once: each check stays one line.
struct Refusal {
  std::string message;
};

std::optional<double> number_at(const json& body, const char* key, double min, double max) {
  if (!body.contains(key)) return std::nullopt;
  const json& v = body[key];
  if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < min ||
      v.get<double>() > max) {
    throw Refusal{std::string(key) + ": must be a number from " + std::to_string(min) + " to " +
                  std::to_string(max)};
  }
  return v.get<double>();
}

std::vector<std::string> sources_from(const json& body) {
  if (!body.contains("sources") || !body["sources"].is_array() || body["sources"].empty() ||
      body["sources"].size() > 64) {
    throw Refusal{"sources: must be a list of 1 to 64 source names (\"sun\", \"casa\", …)"};
  }
  std::vector<std::string> out;
  for (const json& s : body["sources"]) {
    if (!s.is_string() || s.get<std::string>().empty() || s.get<std::string>().size() > 40) {
      throw Refusal{"sources: each must be a name of 1 to 40 characters"};
    }
    out.push_back(s.get<std::string>());
  }
  return out;
}

calibration::ScanSpec spec_from(const json& body) {
  calibration::ScanSpec spec;
  if (body.contains("kind")) {
    const Refusal bad{"kind: must be \"cross\", \"five-point\" or \"raster\""};
    if (!body["kind"].is_string()) throw bad;
    const auto kind = calibration::parse_scan_kind(body["kind"].get<std::string>());
    if (!kind) throw bad;
    spec.kind = *kind;
  }
  const auto beam = number_at(body, "beamwidth_deg", 0.0, calibration::ScanSpec::kMaxBeamwidthDeg);
  if (!beam || !(*beam > 0.0)) throw Refusal{"beamwidth_deg: must be above 0 and at most 30"};
  spec.beamwidth_deg = *beam;
  if (const auto n = number_at(body, "points_per_line", 5, 101)) {
    if (std::fmod(*n, 2.0) != 1.0) throw Refusal{"points_per_line: must be odd, 5 to 101"};
    spec.points_per_line = static_cast<std::size_t>(*n);
  }
  spec.half_span_beams = number_at(body, "half_span_beams", 0.5, 10.0).value_or(2.0);
  if (auto plan = calibration::plan_scan(spec); !plan) {
    const std::string& why = plan.error().message;
    throw Refusal{why.substr(0, why.find(' ')) + ": " + why};
  }
  return spec;
}

CalibrationRequest read(const json& body) {
  CalibrationRequest r;
  r.sources = sources_from(body);
  r.hours = number_at(body, "hours", 0.01, 48.0).value_or(r.hours);
  r.spec = spec_from(body);
  r.timing.settle_s = number_at(body, "settle_s", 0.0, 60.0).value_or(r.timing.settle_s);
  r.timing.dwell_s = number_at(body, "dwell_s", 0.1, 60.0).value_or(r.timing.dwell_s);
  r.sun_every_min = number_at(body, "sun_every_min", 0.0, 1440.0).value_or(r.sun_every_min);
  if (body.contains("refine")) {
    if (!body["refine"].is_boolean()) throw Refusal{"refine: must be true or false"};
    r.refine = body["refine"].get<bool>();
  }
  r.max_scans = static_cast<std::size_t>(number_at(body, "max_scans", 1, 1000).value_or(60));
  return r;
}

}  // namespace

json CalibrationRequest::to_json() const {
  return {{"sources", sources},
          {"hours", hours},
          {"kind", std::string(calibration::to_string(spec.kind))},
          {"beamwidth_deg", spec.beamwidth_deg},
          {"points_per_line", spec.points_per_line},
          {"half_span_beams", spec.half_span_beams},
          {"settle_s", timing.settle_s},
          {"dwell_s", timing.dwell_s},
          {"sun_every_min", sun_every_min},
          {"refine", refine},
          {"max_scans", max_scans}};
}

Result<CalibrationRequest> calibration_request_from(const json& body) {
  if (!body.is_object()) return fail("body: must be a JSON object");
  try {
    return read(body);
  } catch (const Refusal& r) {
    return fail(r.message);
  }
}

}  // namespace azt::app
