#pragma once
// One place the station's element sets come from, as the feed keeps it (element_feed.hpp): a
// URL fetched on a schedule, the configured file, or what operators uploaded; its last accepted
// sets, and when it last succeeded and last failed and why, for /api/state
// (docs/web-api.md: `satellites.sources`).

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/orbit/element_screening.hpp"

namespace azt::app {

enum class SourceKind { Download, File, Upload };

using ElementSets = std::shared_ptr<const std::vector<orbit::Elements>>;

struct ElementSource {
  SourceKind kind = SourceKind::Download;
  std::string url;  ///< the URL; the file's path; "upload"
  /// The last accepted sets: shared with the worker's jobs, never changed in place (a new
  /// download replaces the pointer on the loop). Never null.
  ElementSets sets = std::make_shared<const std::vector<orbit::Elements>>();
  std::optional<double> last_ok_unix_s;
  std::optional<double> last_error_unix_s;
  std::string last_error;   ///< empty after a success
  double due_unix_s = 0.0;  ///< next fetch (downloads only)

  /// {"url","kind","last_ok","last_error","last_error_at","count"}: times ISO 8601 UTC or null.
  [[nodiscard]] nlohmann::json to_json() const;
  /// A failure: the old sets stay in use.
  void failed(std::string why, double unix_s);
  void succeeded(ElementSets fresh, double unix_s);
};

std::string_view kind_name(SourceKind kind);

/// A downloaded or uploaded text read with the element-set readers (TLE; OMM XML, JSON, KVN,
/// CSV; SatNOGS DB's TLE JSON), as the screening takes it.
orbit::ElementDownload read_element_text(std::string_view text, const std::string& source_name);

}  // namespace azt::app
