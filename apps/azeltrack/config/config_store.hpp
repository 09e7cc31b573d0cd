#pragma once

#include <toml++/toml.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/util/result.hpp"
#include "common/off_loop.hpp"
#include "config/daemon_config.hpp"

namespace azt::app {

/// The daemon's configuration file as the one place settings change at runtime
/// (docs/configuration.md, docs/daemon.md "Configuration").
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
///
/// A corrupt primary found while saving is never silently replaced by the older `.bak` (that
/// would drop the last save): the save starts from the version this process last wrote or
/// loaded (the backup only if it loaded that, with a warning at the time), and the corrupt file
/// is set aside as `FILE.corrupt`. When another program saved after this one (FILE.bak is then
/// this program's own version), that save is what the corruption lost: the save is refused,
/// saying so, and nothing is written.
///
/// The daemon saves off its event loop: save_base() on the loop, save_change() on a worker
/// (it waits for the lock and fsyncs), commit() back on the loop. update() is the three at once.
class ConfigStore {
 public:
  /// Throws UsageError (key and line, or both files' problems) when nothing usable is found.
  static ConfigStore open(const std::string& path);

  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const DaemonConfig& config() const { return config_; }
  /// The file as this process last loaded or saved it (migrated): what the settings show.
  [[nodiscard]] const toml::table& root() const { return root_; }
  /// Things to log loudly: a fallback to the backup, migrations applied in memory.
  [[nodiscard]] const std::vector<std::string>& notices() const { return notices_; }
  /// Removes the temp files of writers that were killed mid-save (`FILE.tmp.PID` of a PID that
  /// no longer runs), as the daemon does at start; the notice to log when there were some.
  [[nodiscard]] std::optional<std::string> remove_stale_temps() const;

  using Change = std::function<void(toml::table&)>;

  /// Applies `change` to the current document and saves it if the result is valid. `change` may
  /// throw UsageError to refuse. On success config() is the saved configuration.
  Result<bool> update(const Change& change);

  /// What a save starts from, copied so that the save may run on another thread.
  struct SaveBase {
    std::string path;
    std::string text;               ///< the version this process last wrote or loaded
    bool text_from_backup = false;  ///< loaded from FILE.bak because the primary was corrupt
    double lock_wait_s = 5.0;       ///< how long to wait for another program's lock
  };
  /// A save that reached the disk, to commit() on the thread that owns the store.
  struct Saved {
    toml::table root;
    DaemonConfig config;
    std::string text;
    std::vector<std::string> notices;  ///< to log: a corrupt primary set aside
  };
  [[nodiscard]] SaveBase save_base() const;
  /// Locks, re-reads, applies `change`, validates and writes. Touches no member of any store:
  /// safe on a worker thread while the store is read elsewhere.
  static Result<Saved> save_change(const SaveBase& base, const Change& change);
  /// Makes `saved` the store's configuration (after save_change succeeded).
  void commit(Saved saved);
  /// save_change through `offload` (the lock wait, the writes and the fsyncs off the event
  /// loop), then, back on the loop, commit() and `done` with the notices to log, or why the save
  /// failed (the store unchanged). Saves asked for in order reach the disk in order.
  void save_off_loop(const Offload& offload, Change change,
                     std::function<void(Result<std::vector<std::string>>)> done);

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
  std::string text_;               ///< the file's text as this process last wrote or loaded it
  bool text_from_backup_ = false;  ///< text_ came from FILE.bak (the primary was corrupt at open)
};

}  // namespace azt::app
