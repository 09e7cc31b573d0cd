#pragma once

#include <toml++/toml.h>

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "config/config_choice.hpp"
#include "config/config_migrations.hpp"
#include "config/config_schema.hpp"

namespace azt::app {

class ConfigFile;

/// One table of the configuration file, checked against its section of the schema
/// (config_schema.hpp) when it is made: an unknown key, a wrong type, a value out of range or not
/// among the choices throws UsageError naming the file, the line and the key ("config sim.toml:
/// line 4: [sim.az].encoder_bits must be an integer"). Reading a key the schema does not describe
/// is the program's own mistake: std::logic_error.
class ConfigSection {
 public:
  /// `node` is the table (null when absent); anything else is refused naming `name`.
  static ConfigSection checked(const ConfigFile& file, const toml::node* node, std::string name,
                               const SectionSpec& spec);

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
  /// A text list's strings; a key that also takes one string alone (KeySpec::text_alone) gives
  /// it as a list of one.
  [[nodiscard]] std::optional<std::vector<std::string>> text_list(std::string_view key) const;
  /// A choice key read into its enum ([antenna] backend); `fallback` when absent. The schema
  /// has already refused a name that is not a choice.
  template <typename Enum, std::size_t N>
  [[nodiscard]] Enum choice(std::string_view key, const ConfigChoices<Enum, N>& choices,
                            Enum fallback) const {
    const auto name = text(key);
    if (!name) return fallback;
    const auto value = choose(choices, *name);
    if (!value) throw std::logic_error("the schema's choices of " + std::string(key) + " differ");
    return *value;
  }
  /// A sub-table ("az" of [mount]: [mount.az]), checked (absent: present() is false).
  [[nodiscard]] ConfigSection child(std::string_view key) const;
  /// A child array of tables ("transmitter" of [satellites]: [[satellites.transmitter]]), each
  /// item checked; items are named "satellites.transmitter#1" … in errors.
  [[nodiscard]] std::vector<ConfigSection> child_array(std::string_view key) const;

  /// Throws UsageError "config FILE: [name].key: what".
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;

 private:
  ConfigSection(const ConfigFile& file, const toml::table* table, std::string name,
                const SectionSpec& spec)
      : file_(file), table_(table), name_(std::move(name)), spec_(&spec) {}
  /// Every key present against the schema.
  void check_keys() const;
  /// The schema's description of `key`, which the reader means to read as `type`.
  const KeySpec& key_spec(std::string_view key, std::initializer_list<KeyType> types) const;
  const toml::node* node(std::string_view key) const;

  const ConfigFile& file_;
  const toml::table* table_;
  std::string name_;
  const SectionSpec* spec_;
};

/// A parsed TOML configuration file whose top-level tables are all known.
class ConfigFile {
 public:
  /// Reads and parses; throws UsageError with line and column on a syntax error, or when a
  /// top-level key is not a table of the schema (one file serves every subcommand).
  static ConfigFile load(const std::string& path);
  /// The same from text already read; `path` names the file in errors. Older schema versions are
  /// migrated in memory (migration() says how); a newer one is refused.
  static ConfigFile parse(std::string_view text, const std::string& path);

  /// A top-level table ("control"), checked against the schema.
  [[nodiscard]] ConfigSection section(std::string_view name) const;
  [[nodiscard]] const toml::table& root() const { return root_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const MigrationReport& migration() const { return migration_; }
  /// An array of tables (`[[serial]]`), each item checked against the schema; items are named
  /// "serial#1", "serial#2" … in errors.
  [[nodiscard]] std::vector<ConfigSection> section_array(std::string_view name) const;
  [[noreturn]] void fail(const std::string& what) const;

 private:
  ConfigFile(std::string path, toml::table root) : path_(std::move(path)), root_(std::move(root)) {}
  std::string path_;
  toml::table root_;
  MigrationReport migration_;
};

}  // namespace azt::app
