#include "calibration/pointing_history.hpp"

#include <cmath>

#include "azt/calibration/term_selection.hpp"
#include "azt/util/text_lines.hpp"
#include "calibration/fit_report.hpp"

namespace azt::app {

using nlohmann::json;

PointingHistory PointingHistory::parse(std::string_view text, std::size_t& skipped) {
  PointingHistory h;
  skipped = 0;
  for (const std::string_view line : split_lines(text)) {
    if (line.empty()) continue;
    json record = json::parse(line, nullptr, false);
    const bool ok = record.is_object() && record.contains("id") &&
                    record["id"].is_number_integer() && static_cast<bool>(terms_of(record));
    if (ok) {
      h.records_.push_back(std::move(record));
    } else {
      ++skipped;
    }
  }
  return h;
}

json PointingHistory::record(const calibration::PointingTerms& terms,
                             std::optional<double> rms_after_deg, std::size_t scans,
                             const std::string& why, const std::string& utc) const {
  long long id = 1;
  for (const json& r : records_) id = std::max(id, r["id"].get<long long>() + 1);
  return {{"id", id},
          {"utc", utc},
          {"terms", terms_json(terms)},
          {"rms_after_deg", rms_after_deg ? json(*rms_after_deg) : json(nullptr)},
          {"scans", scans},
          {"why", why}};
}

const json* PointingHistory::find(long long id) const {
  for (const json& r : records_) {
    if (r["id"].get<long long>() == id) return &r;
  }
  return nullptr;
}

Result<calibration::PointingTerms> PointingHistory::terms_of(const json& record) {
  if (!record.contains("terms") || !record["terms"].is_object()) return fail("no terms");
  std::array<double, calibration::PointingTerms::kCount> v{};
  for (std::size_t i = 0; i < v.size(); ++i) {
    const json& t = record["terms"].value(calibration::term_key(i), json(nullptr));
    if (!t.is_number() || !std::isfinite(t.get<double>()) || std::fabs(t.get<double>()) > 10.0) {
      return fail(std::string("terms: ") + calibration::term_key(i) + " is not a term within ±10°");
    }
    v.at(i) = t.get<double>();
  }
  return calibration::PointingTerms::from_array(v);
}

json PointingHistory::newest_first() const {
  json list = json::array();
  for (auto it = records_.rbegin(); it != records_.rend(); ++it) list.push_back(*it);
  return {{"models", list}};
}

}  // namespace azt::app
