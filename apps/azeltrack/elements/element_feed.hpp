#pragma once
// Where the station's satellites come from (docs/satellites.md, "Elements from the network"):
// `[satellites] sources` fetched at start and every `refresh_h`, the configured file, and what
// an operator uploads, each screened before use (azt/orbit/element_screening.hpp), merged by
// NORAD number (the newest epoch wins) and published to the tracker as one whole catalogue.
//
// Threads: downloads run through `download_offload` (a worker of their own: a stalled server
// must not hold up a login or a save), reading, merging and the cache's atomic write through
// `offload`; the state below is touched only on the loop, where the `done` halves run. A failed
// source keeps its previous sets in the merge and says why in to_json().

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "azt/orbit/element_screening.hpp"
#include "azt/util/result.hpp"
#include "common/off_loop.hpp"
#include "elements/element_source.hpp"
#include "satellites/satellite_catalogue.hpp"

namespace azt::app {

struct ElementFeedSettings {
  std::string file;                  ///< [satellites] file, absolute; empty: none
  std::vector<std::string> sources;  ///< [satellites] sources, in order
  double refresh_s = 12.0 * 3600.0;
  std::string cache_path;  ///< empty: no cache
  orbit::ScreeningLimits limits;
  std::size_t max_cache_bytes = std::size_t{256} * 1024 * 1024;
};

/// Fetches one URL, blocking (on the download worker): the body, or why not.
using FetchElements = std::function<Result<std::string>(const std::string& url)>;

struct ElementFeedParts {
  ElementFeedSettings settings;
  FetchElements fetch;
  Offload download_offload;
  Offload offload;
  std::function<double()> unix_now;  ///< UTC, Unix seconds (the daemon's clock; tests' own)
  /// Takes the new catalogue, on the loop.
  std::function<void(SatelliteCatalogue, double unix_s)> publish;
  std::function<void(const std::string&)> log;
};

class ElementFeed {
 public:
  explicit ElementFeed(ElementFeedParts parts);

  /// Before the loop runs, on the caller's thread: the cache and the file are read and the
  /// catalogue published at once (the start target may be a satellite); downloads follow from
  /// the first tick().
  void start(double unix_s);
  /// Every control tick: the file looked at every 10 s, the sources that are due fetched.
  void tick(double unix_s);
  /// Every download source fetched now (the console's Refresh). False while a round runs.
  bool refresh_now(double unix_s);
  /// An operator's element file: screened like a download (parse, checksums, epochs), merged
  /// into the upload source (the newest epoch per satellite), then published; `done` gets
  /// {"count","newer","not_newer"} or why it was refused, on the loop.
  void upload(std::string text, double unix_s, std::function<void(Result<nlohmann::json>)> done);

  /// [{url, kind, last_ok, last_error, last_error_at, count}] (element_source.hpp).
  [[nodiscard]] nlohmann::json to_json() const;
  [[nodiscard]] bool fetching() const { return fetching_; }

 private:
  struct Fetched {
    std::size_t index = 0;
    ElementSets sets;  ///< null: refused or failed
    std::string error;
    bool transport = false;  ///< no answer at all (DNS, connect, timeout): worth a retry soon
  };
  void load_cache();
  void poll_file(double unix_s);
  void read_file(bool at_once);
  void fetch_due(double unix_s);
  void take_fetched(const std::vector<Fetched>& results, double unix_s);
  void publish(double unix_s, bool at_once);
  [[nodiscard]] double retry_s(const Fetched& fetched) const;
  ElementSource* file_source();
  ElementSource& upload_source();

  ElementFeedParts p_;
  std::vector<ElementSource> sources_;  ///< downloads in order, then the file, then uploads
  bool fetching_ = false;
  bool reading_file_ = false;
  double last_poll_s_ = -1e9;
  std::optional<double> file_mtime_;
  unsigned publishes_ = 0;  ///< the newest publish wins when two overlap
  std::size_t last_count_ = 0;
};

}  // namespace azt::app
