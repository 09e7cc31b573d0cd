#include "config/config_store.hpp"

#include <filesystem>
#include <memory>
#include <sstream>

#include "azt/linux/atomic_file.hpp"
#include "azt/linux/file_lock.hpp"
#include "common/usage_error.hpp"
#include "config/config_file.hpp"
#include "config/config_text_edit.hpp"
#include "config/toml_text.hpp"

namespace azt::app {
namespace {

/// What counts as a corrupt (not merely wrong) file: not TOML at all, or nothing but whitespace
/// (a truncated or zeroed file parses as an empty table, which would mean "all defaults").
Result<bool> parses_as_toml(std::string_view text) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) return fail("the file is empty");
  try {
    (void)toml::parse(text);
  } catch (const toml::parse_error& e) {
    return fail("line " + std::to_string(e.source().begin.line) + ": " +
                std::string(e.description()));
  }
  return true;
}

struct Loaded {
  std::string text;  ///< as read (from the backup when from_backup)
  toml::table root;
  DaemonConfig config;
  bool migrated = false;
  bool from_backup = false;
  std::vector<std::string> notices;
};

/// Parses `text` (read from `name`), migrates in memory, validates. Throws UsageError.
Loaded parse_loaded(std::string text, const std::string& name, const std::string& path) {
  Loaded out;
  const ConfigFile file = ConfigFile::parse(text, name);
  out.config = daemon_config_from(file);
  for (const auto& change : file.migration().changes) {
    std::string notice = "config " + path + ": migrated in memory: ";
    notice += change;
    notice += " (saved with the next change)";
    out.notices.push_back(std::move(notice));
  }
  out.root = file.root();
  out.migrated = !file.migration().changes.empty();
  out.text = std::move(text);
  return out;
}

/// Reads, falls back to the backup only for corruption, migrates, validates. Throws UsageError.
Loaded load(const std::string& path) {
  auto text = linux_os::load_with_backup(path, parses_as_toml);
  if (!text) throw UsageError("config " + text.error().message);
  const bool from_backup = text->from_backup;
  std::vector<std::string> notices;
  if (from_backup) notices.push_back("config " + text->warning);
  Loaded out = parse_loaded(std::move(text.value().text), from_backup ? path + ".bak" : path, path);
  out.from_backup = from_backup;
  notices.insert(notices.end(), out.notices.begin(), out.notices.end());
  out.notices = std::move(notices);
  return out;
}

/// The text a save starts from: the primary as it is now, or, when it is corrupt, the base's
/// own version if that is known to be the newest good one (ConfigStore's class comment).
/// Sets `corrupt` when the primary must be set aside.
Result<std::string> current_text(const ConfigStore::SaveBase& base, bool& corrupt,
                                 std::vector<std::string>& notices) {
  const std::string& path = base.path;
  std::string problem;
  if (auto primary = linux_os::read_file(path); primary.ok()) {
    auto valid = parses_as_toml(*primary);
    if (valid.ok()) return std::move(primary).value();
    problem = valid.error().message;
  } else {
    problem = primary.error().message;
  }
  corrupt = true;
  const std::string head = "'" + path + "' is corrupt (" + problem + ")";
  // After this program's last save, FILE.bak is the version before it; if FILE.bak is this
  // program's own version, someone saved after it, and that save is what the corruption lost.
  if (!base.text_from_backup) {
    if (auto backup = linux_os::read_file(path + ".bak"); backup.ok() && *backup == base.text) {
      return fail(head +
                  " and another program saved it after this one last did; that save "
                  "cannot be recovered here; nothing saved: repair '" +
                  path + "' or restore it from '" + path + ".bak' (the version before that save)");
    }
  }
  notices.push_back("config " + head + ": set aside as '" + path + ".corrupt'; saved from " +
                    (base.text_from_backup
                         ? "'" + path + ".bak', which this program loaded (and said so) at start"
                         : std::string("the version this program last wrote or loaded")));
  return base.text;
}

/// Splits "park.2.az_deg" at the dots; empty segments are an error.
std::vector<std::string> split_key(std::string_view key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    const auto part = key.substr(start, dot == std::string_view::npos ? key.npos : dot - start);
    if (part.empty()) throw UsageError("key '" + std::string(key) + "' has an empty part");
    parts.emplace_back(part);
    if (dot == std::string_view::npos) return parts;
    start = dot + 1;
  }
}

/// "2" -> 2; anything but a short run of digits -> 0 (no such item).
std::size_t item_number(std::string_view part) {
  if (part.empty() || part.size() > 4) return 0;
  if (part.find_first_not_of("0123456789") != std::string_view::npos) return 0;
  return std::stoul(std::string(part));
}

/// An item of an array of tables by its 1-based number, as error messages name them ("park#2").
toml::table& array_item(toml::array& a, const std::string& name, const std::string& part) {
  const std::size_t n = item_number(part);
  if (n < 1 || n > a.size() || !a.get(n - 1)->is_table()) {
    throw UsageError("'" + name + "' has no table item " + part + " (items are " + name + ".1 to " +
                     name + "." + std::to_string(a.size()) + ")");
  }
  return *a.get(n - 1)->as_table();
}

/// The table that holds the last part of `parts`: tables are created on the way, array items
/// must exist.
toml::table& parent_table(toml::table& root, const std::vector<std::string>& parts) {
  toml::table* t = &root;
  const std::size_t last = parts.size() - 1;
  for (std::size_t i = 0; i < last; ++i) {
    toml::node* n = t->get(parts[i]);
    if (n == nullptr) {
      t = t->insert(parts[i], toml::table{}).first->second.as_table();
    } else if (n->is_table()) {
      t = n->as_table();
    } else if (n->is_array() && i + 1 < last) {
      t = &array_item(*n->as_array(), parts[i], parts[i + 1]);
      ++i;
    } else {
      throw UsageError("'" + parts[i] + "' is not a table");
    }
  }
  return *t;
}

const toml::node* find(const toml::table& root, std::string_view key) {
  const toml::node* n = &root;
  for (const auto& part : split_key(key)) {
    if (const toml::table* t = n->as_table()) {
      n = t->get(part);
    } else if (const toml::array* a = n->as_array()) {
      const std::size_t i = item_number(part);
      n = i >= 1 && i <= a->size() ? a->get(i - 1) : nullptr;
    } else {
      n = nullptr;
    }
    if (n == nullptr) return nullptr;
  }
  return n;
}

}  // namespace

ConfigStore ConfigStore::open(const std::string& path) {
  Loaded loaded = load(path);
  ConfigStore store(path, std::move(loaded.root), std::move(loaded.config));
  store.notices_ = std::move(loaded.notices);
  store.text_ = std::move(loaded.text);
  store.text_from_backup_ = loaded.from_backup;
  return store;
}

std::optional<std::string> ConfigStore::remove_stale_temps() const {
  // Temps of writers killed mid-save (each a full copy of the file): nobody will finish them.
  const std::size_t n = linux_os::remove_stale_temp_files(path_);
  if (n == 0) return std::nullopt;
  return "config " + path_ + ": removed " + std::to_string(n) +
         " temp file(s) left by interrupted saves";
}

std::string ConfigStore::serialize(const toml::table& root) {
  std::ostringstream out;
  out << "# azeltrack configuration, schema " << kSchemaVersion
      << ", saved by azeltrack (docs/configuration.md).\n"
         "# The previous version of this file is kept beside it as <name>.bak.\n\n"
      << toml_text(root) << '\n';
  return out.str();
}

ConfigStore::SaveBase ConfigStore::save_base() const {
  return SaveBase{path_, text_, text_from_backup_};
}

Result<ConfigStore::Saved> ConfigStore::save_change(const SaveBase& base, const Change& change) {
  const std::string& path = base.path;
  auto lock = linux_os::FileLock::acquire(path + ".lock", base.lock_wait_s);
  if (!lock) return lock.error();
  Saved saved;
  bool corrupt = false;
  // Another writer may have saved since we loaded: change what is on disk now.
  auto text = current_text(base, corrupt, saved.notices);
  if (!text) return text.error();
  try {
    Loaded current = parse_loaded(std::move(text).value(), path, path);
    saved.root = std::move(current.root);
    change(saved.root);
    // Keep the author's comments and layout where the change allows; a migration rewrites.
    std::optional<std::string> edited;
    if (!current.migrated) {
      edited = edit_toml_text(current.text, toml::parse(current.text), saved.root);
    }
    saved.text = edited ? std::move(*edited) : serialize(saved.root);
    saved.config = daemon_config_from(ConfigFile::parse(saved.text, path));
  } catch (const UsageError& e) {
    return fail(e.what());
  }
  if (corrupt) {
    // Keep the corrupt primary for a post-mortem, and out of the .bak rotation.
    std::error_code ec;
    std::filesystem::rename(path, path + ".corrupt", ec);
    if (ec && std::filesystem::exists(path)) {
      return fail("cannot set the corrupt '" + path + "' aside: " + ec.message());
    }
  }
  auto written = linux_os::write_file_atomically(path, saved.text);
  if (!written) return written.error();
  return saved;
}

void ConfigStore::commit(Saved saved) {
  root_ = std::move(saved.root);
  config_ = std::move(saved.config);
  text_ = std::move(saved.text);
  text_from_backup_ = false;
}

void ConfigStore::save_off_loop(const Offload& offload, Change change,
                                std::function<void(Result<std::vector<std::string>>)> done) {
  auto outcome =
      std::make_shared<Result<Saved>>(fail("the save was interrupted (see the daemon's log)"));
  offload([base = save_base(), change = std::move(change),
           outcome] { *outcome = save_change(base, change); },
          [this, outcome, done = std::move(done)] {
            if (!*outcome) {
              done(outcome->error());
              return;
            }
            std::vector<std::string> notices = outcome->value().notices;
            commit(std::move(*outcome).value());
            done(std::move(notices));
          });
}

Result<bool> ConfigStore::update(const Change& change) {
  auto saved = save_change(save_base(), change);
  if (!saved) return saved.error();
  for (auto& notice : saved.value().notices) notices_.push_back(std::move(notice));
  commit(std::move(saved).value());
  return true;
}

Result<bool> ConfigStore::set(std::string_view key, std::string_view value) {
  toml::table parsed;
  try {
    parsed = toml::parse("value = " + std::string(value));
  } catch (const toml::parse_error& e) {
    return fail("'" + std::string(value) +
                "' is not a TOML value (strings need quotes): " + std::string(e.description()));
  }
  return update([&](toml::table& root) {
    const auto parts = split_key(key);
    parent_table(root, parts).insert_or_assign(parts.back(), *parsed.get("value"));
  });
}

std::optional<std::string> ConfigStore::get(std::string_view key) const {
  const toml::node* n = nullptr;
  try {
    n = find(root_, key);
  } catch (const UsageError&) {
    return std::nullopt;
  }
  if (n == nullptr) return std::nullopt;
  return toml_text(*n);
}

}  // namespace azt::app
