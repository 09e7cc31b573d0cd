#include "calibration/fit_report.hpp"

#include <string>

#include "azt/calibration/term_selection.hpp"

namespace azt::app {
namespace {

nlohmann::json residual_json(const calibration::ObservationResidual& r,
                             const calibration::ScanLogEntry* row) {
  nlohmann::json j{{"xel_before_deg", r.before.xel_deg},
                   {"el_before_deg", r.before.el_deg},
                   {"xel_after_deg", r.after.xel_deg},
                   {"el_after_deg", r.after.el_deg},
                   {"used", r.used}};
  if (row != nullptr) {
    j["utc"] = astro::format_iso8601_utc(row->utc);
    j["source"] = row->source;
    j["az_deg"] = row->az_deg;
    j["el_deg"] = row->el_deg;
    j["measured"] = std::string(calibration::to_string(row->measured));
  }
  return j;
}

}  // namespace

nlohmann::json terms_json(const calibration::PointingTerms& terms) {
  nlohmann::json j = nlohmann::json::object();
  const auto v = terms.as_array();
  for (std::size_t i = 0; i < v.size(); ++i) j[calibration::term_key(i)] = v.at(i);
  return j;
}

nlohmann::json fit_json(const calibration::PointingFit& fit,
                        const std::vector<calibration::ScanLogEntry>& rows) {
  nlohmann::json held = nlohmann::json::object();
  for (std::size_t i = 0; i < fit.held.size(); ++i) {
    if (!fit.held.at(i).empty()) held[calibration::term_key(i)] = fit.held.at(i);
  }
  nlohmann::json residuals = nlohmann::json::array();
  for (std::size_t i = 0; i < fit.residuals.size(); ++i) {
    residuals.push_back(residual_json(fit.residuals[i], i < rows.size() ? &rows[i] : nullptr));
  }
  return {{"terms", terms_json(fit.terms)},
          {"std_errors", terms_json(fit.std_errors)},
          {"rms_before_deg", fit.rms_before_deg},
          {"rms_after_deg", fit.rms_deg},
          {"max_after_deg", fit.max_deg},
          {"scans", fit.observations},
          {"held", held},
          {"residuals", residuals}};
}

}  // namespace azt::app
