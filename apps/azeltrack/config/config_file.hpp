#pragma once

#include <toml++/toml.h>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "config/config_migrations.hpp"

namespace azt::app {

class ConfigFile;

/// One table of the configuration file. Every accessor throws UsageError naming the file and the
/// key ("config sim.toml: [sim.az].encoder_bits must be an integer") on a wrong type.
class ConfigSection {
 public:
  ConfigSection(const ConfigFile& file, const toml::table* table, std::string name)
      : file_(file), table_(table), name_(std::move(name)) {}

  [[nodiscard]] bool present() const { return table_ != nullptr; }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] bool has(std::string_view key) const;
  /// The key is present and holds a string (for keys that take a number or a string).
  [[nodiscard]] bool is_text(std::string_view key) const;

  [[nodiscard]] std::optional<double> number(std::string_view key) const;
  [[nodiscard]] std::optional<std::int64_t> integer(std::string_view key) const;
  [[nodiscard]] std::optional<std::string> text(std::string_view key) const;
  [[nodiscard]] std::optional<bool> boolean(std::string_view key) const;
  [[nodiscard]] const toml::array* array(std::string_view key) const;
  /// A sub-table, checked against its allowed keys (absent: present() is false).
  [[nodiscard]] ConfigSection child(std::string_view key,
                                    std::initializer_list<std::string_view> allowed) const;

  /// Throws UsageError "config FILE: [name].key: what".
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;

 private:
  const toml::node* node(std::string_view key) const;

  const ConfigFile& file_;
  const toml::table* table_;
  std::string name_;
};

/// A parsed TOML configuration file whose top-level tables are all known.
class ConfigFile {
 public:
  /// Reads and parses; throws UsageError with line and column on a syntax error, or when a
  /// top-level key is not a table azeltrack knows (one file serves every subcommand: station,
  /// sky, atmosphere, control, geometry, park, sim).
  static ConfigFile load(const std::string& path);
  /// The same from text already read; `path` names the file in errors. Older schema versions are
  /// migrated in memory (migration() says how); a newer one is refused.
  static ConfigFile parse(std::string_view text, const std::string& path);

  /// A top-level table, checked against its allowed keys.
  [[nodiscard]] ConfigSection section(std::string_view name,
                                      std::initializer_list<std::string_view> allowed) const;
  [[nodiscard]] const toml::table& root() const { return root_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const MigrationReport& migration() const { return migration_; }
  /// An array of tables (`[[serial]]`), each checked against the allowed keys; items are named
  /// "serial#1", "serial#2" … in errors.
  [[nodiscard]] std::vector<ConfigSection> section_array(
      std::string_view name, std::initializer_list<std::string_view> allowed) const;
  [[noreturn]] void fail(const std::string& what) const;

 private:
  ConfigFile(std::string path, toml::table root) : path_(std::move(path)), root_(std::move(root)) {}
  std::string path_;
  toml::table root_;
  MigrationReport migration_;
};

}  // namespace azt::app
