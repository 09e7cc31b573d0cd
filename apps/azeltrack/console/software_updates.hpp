#pragma once
// The console's Software page (docs/packaging.md, the AnTrack-Pro manual's "Software Updating"):
// this program's version, a package uploaded by the logged-in operator handed to the root update
// helper, and what the helper reports. The daemon never runs as root and never installs
// anything: it checks the upload is a Debian archive at all, writes it to the inbox (its own
// folder), and reads the helper's status file. The helper (packaging/azeltrack-update, started
// by a systemd path unit when the inbox's request.deb appears) copies the package, checks its
// name, architecture and version with dpkg, installs it with apt and reports each step.
// docs/packaging.md "Updates from the console".

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "common/off_loop.hpp"
#include "console/console_model.hpp"
#include "console/package_upload.hpp"

namespace azt::app {

class SoftwareUpdates {
 public:
  struct Config {
    std::string version;       ///< this program's (program_version())
    std::string architecture;  ///< the package's; "" for a source build
    /// Where uploads go for the helper (`request.deb` in it); "" when updates are not set up
    /// here (a source build: the unit of the package passes --update-inbox).
    std::string inbox_dir;
    std::string status_file;  ///< what the helper writes about its work
  };
  /// The largest package accepted; the program's own is under 2 MB.
  static constexpr std::size_t kMaxPackageBytes = std::size_t{64} * 1024 * 1024;
  /// A helper report older than this in a working phase is taken as abandoned (a power cut).
  static constexpr double kStaleWorkS = 30.0 * 60.0;

  SoftwareUpdates(Config config, Offload offload, std::function<double()> unix_s)
      : config_(std::move(config)), offload_(std::move(offload)), unix_s_(std::move(unix_s)) {}

  [[nodiscard]] bool enabled() const { return enabled(config_); }
  /// GET /api/software: the version, the last upload and the helper's report (read off the loop).
  void status(ActDone done);
  /// Where POST /api/software/update's body goes as it arrives (updates must be enabled()).
  [[nodiscard]] std::shared_ptr<PackageUpload> start_upload() const;
  /// POST /api/software/update once its body is whole in `upload`: refused when updates are not
  /// set up (409); off the loop, refused when it is no Debian archive (400) or while another
  /// update waits or runs (409), else stored in the inbox (its SHA-256 in the answer).
  void receive(const PackageUpload& upload, ActDone done);

 private:
  struct Upload {
    std::string sha256_hex;
    std::size_t bytes = 0;
    double at_unix_s = 0.0;
  };
  /// What the worker found; turned into JSON back on the loop.
  struct Look {
    nlohmann::json helper;  ///< null: no report yet
    std::string helper_error;
    bool pending = false;  ///< request.deb waits for the helper
  };
  // The worker's halves are static and get what they read by value: a job may still run while
  // this object is destroyed at shutdown, so it never reaches `this`.
  [[nodiscard]] static Look look(const Config& config);  // worker thread
  [[nodiscard]] static std::string request_path(const Config& config);
  [[nodiscard]] static bool enabled(const Config& config) { return !config.inbox_dir.empty(); }
  /// The refusal for a new upload given what the worker found at `now_unix_s`, or nullopt.
  [[nodiscard]] static std::optional<ApiError> busy(const Look& now, double now_unix_s);
  /// Checks the whole package and stores it for the helper: the refusal, or nullopt.
  [[nodiscard]] static std::optional<ApiError> store(ReceivedPackage& package, const Config& config,
                                                     double now_unix_s);
  nlohmann::json to_json(const Look& found) const;

  Config config_;
  Offload offload_;
  std::function<double()> unix_s_;
  std::optional<Upload> last_upload_;  ///< loop thread only
};

}  // namespace azt::app
