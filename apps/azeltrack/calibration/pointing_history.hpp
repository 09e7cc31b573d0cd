#pragma once
// The pointing models the station has used (docs/calibration.md "In the daemon"): every model an
// apply or a restore saved as [pointing], and the one in use before the first apply, each one
// line of `pointing-history.jsonl` beside the configuration: {"id", "utc", "terms",
// "rms_after_deg", "scans", "why"} (why: "fit", "restore", or "in use" for the model found in
// the file). Any of them can be saved as [pointing] again.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/calibration/pointing_model.hpp"
#include "azt/util/result.hpp"

namespace azt::app {

class PointingHistory {
 public:
  PointingHistory() = default;
  /// The file's lines, oldest first; a line that is not a record is skipped and counted in
  /// `skipped` (the rest kept).
  static PointingHistory parse(std::string_view text, std::size_t& skipped);

  /// A new record, numbered after the newest: `rms_after_deg` none for the model in use.
  [[nodiscard]] nlohmann::json record(const calibration::PointingTerms& terms,
                                      std::optional<double> rms_after_deg, std::size_t scans,
                                      const std::string& why, const std::string& utc) const;
  /// A record appended to the file is added here.
  void add(nlohmann::json record) { records_.push_back(std::move(record)); }
  [[nodiscard]] bool empty() const { return records_.empty(); }
  /// The record numbered `id`, or null.
  [[nodiscard]] const nlohmann::json* find(long long id) const;
  /// The terms a record holds.
  static Result<calibration::PointingTerms> terms_of(const nlohmann::json& record);
  /// GET /api/calibration/history: {"models": [...]}, the newest first.
  [[nodiscard]] nlohmann::json newest_first() const;

 private:
  std::vector<nlohmann::json> records_;
};

}  // namespace azt::app
