#pragma once

#include <toml++/toml.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/util/result.hpp"
#include "daemon_config.hpp"

namespace azt::app {

/// The daemon's configuration file as the one place settings change at runtime (README
/// "Configuration", docs/daemon.md "Configuration").
///
/// Loading: a primary that cannot be read or is not TOML (a torn or zeroed file) falls back to
/// `FILE.bak` with a warning in notices(); a primary that is valid TOML but has a bad value is
/// refused with the key and its line, never replaced by the backup (that would hide the user's
/// mistake). Older schema versions are migrated in memory.
///
/// Saving: update() re-reads the file under an advisory lock (so the daemon and `azeltrack config
/// set` never lose each other's changes), applies the change, validates the whole result as
/// `serve` would, and replaces the file atomically (temp + fsync + rename + directory fsync),
/// keeping the previous version as `FILE.bak`. A failed change leaves the file untouched.
/// A save keeps the file's comments and layout, replacing only the text of what changed
/// (config_text_edit.hpp); only a schema migration or an unusual change rewrites it whole.
class ConfigStore {
 public:
  /// Throws UsageError (key and line, or both files' problems) when nothing usable is found.
  static ConfigStore open(const std::string& path);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const DaemonConfig& config() const { return config_; }
  /// Things to log loudly: a fallback to the backup, migrations applied in memory.
  [[nodiscard]] const std::vector<std::string>& notices() const { return notices_; }

  /// Applies `change` to the current document and saves it if the result is valid. `change` may
  /// throw UsageError to refuse. On success config() is the saved configuration.
  Result<bool> update(const std::function<void(toml::table&)>& change);

  /// `key` is dotted ("control.window_deg", "station.grid"); `value` is a TOML value
  /// ("0.2", "\"FN31\"", "true"); `[[array]]` items are addressed as "park.2.az_deg".
  Result<bool> set(std::string_view key, std::string_view value);
  /// The value at `key` as TOML text, or nothing if the key is absent.
  [[nodiscard]] std::optional<std::string> get(std::string_view key) const;

  /// The text a save writes for `root`: a header comment, then the TOML.
  static std::string serialize(const toml::table& root);

 private:
  ConfigStore(std::string path, toml::table root, DaemonConfig config)
      : path_(std::move(path)), root_(std::move(root)), config_(std::move(config)) {}

  std::string path_;
  toml::table root_;
  DaemonConfig config_;
  std::vector<std::string> notices_;
  bool primary_corrupt_ = false;  ///< loaded from .bak: set the bad primary aside before saving
};

}  // namespace azt::app
