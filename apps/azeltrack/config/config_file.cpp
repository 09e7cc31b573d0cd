#include "config/config_file.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "azt/linux/atomic_file.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

/// "line N: " for a node the parser placed, "" otherwise.
std::string line_of(const toml::node& node) {
  const auto line = node.source().begin.line;
  return line > 0 ? "line " + std::to_string(line) + ": " : std::string();
}

const SectionSpec& schema_section(std::string_view name) {
  const SectionSpec* spec = find_section(name);
  if (spec == nullptr) {
    throw std::logic_error("the configuration schema has no [" + std::string(name) + "]");
  }
  return *spec;
}

}  // namespace

ConfigSection ConfigSection::checked(const ConfigFile& file, const toml::node* node,
                                     std::string name, const SectionSpec& spec) {
  const toml::table* table = nullptr;
  if (node != nullptr) {
    table = node->as_table();
    if (table == nullptr) file.fail(line_of(*node) + "[" + name + "] must be a table");
  }
  ConfigSection section(file, table, std::move(name), spec);
  section.check_keys();
  return section;
}

void ConfigSection::check_keys() const {
  if (table_ == nullptr) return;
  for (const auto& [key, value] : *table_) {
    const std::string_view k = key.str();
    if (const KeySpec* spec = find_key(*spec_, k)) {
      if (auto why = key_violation(*spec, value)) fail(k, *why);
    } else if (const SectionSpec* child = find_child(*spec_, k); child == nullptr) {
      file_.fail(line_of(value) + "unknown key [" + name_ + "]." + std::string(k));
    } else if (child->array_of_tables) {
      // [[satellites.transmitter]]: each item is checked when child_array() reads it.
      if (!value.is_array()) {
        file_.fail(line_of(value) + "[[" + name_ + "." + std::string(k) +
                   "]] must be an array of tables");
      }
    } else if (!value.is_table()) {
      file_.fail(line_of(value) + "[" + name_ + "." + std::string(k) + "] must be a table");
    }
  }
}

const KeySpec& ConfigSection::key_spec(std::string_view key,
                                       std::initializer_list<KeyType> types) const {
  const KeySpec* spec = find_key(*spec_, key);
  if (spec == nullptr || std::find(types.begin(), types.end(), spec->type) == types.end()) {
    throw std::logic_error("the configuration schema does not describe [" +
                           std::string(spec_->name) + "]." + std::string(key) +
                           " as this reader reads it");
  }
  return *spec;
}

std::vector<ConfigSection> ConfigSection::child_array(std::string_view key) const {
  const SectionSpec* spec = find_child(*spec_, key);
  if (spec == nullptr || !spec->array_of_tables) {
    throw std::logic_error("the configuration schema has no [[" + name_ + "." + std::string(key) +
                           "]]");
  }
  std::vector<ConfigSection> out;
  const toml::node* n = node(key);
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  for (std::size_t i = 0; a != nullptr && i < a->size(); ++i) {
    const std::string item = name_ + "." + std::string(key) + "#" + std::to_string(i + 1);
    out.push_back(checked(file_, a->get(i), item, *spec));
  }
  return out;
}

const toml::node* ConfigSection::node(std::string_view key) const {
  return table_ == nullptr ? nullptr : table_->get(key);
}

bool ConfigSection::has(std::string_view key) const { return node(key) != nullptr; }

bool ConfigSection::is_text(std::string_view key) const {
  const toml::node* n = node(key);
  return n != nullptr && n->is_string();
}

void ConfigSection::fail(std::string_view key, const std::string& what) const {
  const toml::node* n = node(key);
  const auto line =
      n != nullptr ? n->source().begin.line : (table_ != nullptr ? table_->source().begin.line : 0);
  file_.fail((line > 0 ? "line " + std::to_string(line) + ": " : std::string()) + "[" + name_ +
             "]." + std::string(key) + " " + what);
}

std::optional<double> ConfigSection::number(std::string_view key) const {
  (void)key_spec(key, {KeyType::Number});
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  auto v = n->value<double>();  // integers too
  if (!v || !std::isfinite(*v)) fail(key, "must be a finite number");
  return v;
}

std::optional<std::int64_t> ConfigSection::integer(std::string_view key) const {
  (void)key_spec(key, {KeyType::Integer, KeyType::GpioLine});
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_integer()) fail(key, "must be an integer");
  return n->value<std::int64_t>();
}

std::optional<std::string> ConfigSection::text(std::string_view key) const {
  (void)key_spec(key, {KeyType::Text, KeyType::Choice, KeyType::GpioLine});
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  auto v = n->value<std::string>();
  if (!v) fail(key, "must be a string");
  return v;
}

std::optional<bool> ConfigSection::boolean(std::string_view key) const {
  (void)key_spec(key, {KeyType::Boolean});
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_boolean()) fail(key, "must be true or false");
  return n->value<bool>();
}

const toml::array* ConfigSection::array(std::string_view key) const {
  (void)key_spec(key, {KeyType::TextList, KeyType::NumberList, KeyType::IntegerList});
  const toml::node* n = node(key);
  if (n == nullptr) return nullptr;
  if (!n->is_array()) fail(key, "must be an array");
  return n->as_array();
}

std::optional<std::vector<std::string>> ConfigSection::text_list(std::string_view key) const {
  const KeySpec& spec = key_spec(key, {KeyType::TextList});
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (spec.text_alone && n->is_string()) return std::vector<std::string>{n->as_string()->get()};
  if (!n->is_array()) fail(key, "must be an array");
  std::vector<std::string> out;
  for (const auto& item : *n->as_array()) {
    if (!item.is_string()) fail(key, "must hold strings");
    out.push_back(item.as_string()->get());
  }
  return out;
}

ConfigSection ConfigSection::child(std::string_view key) const {
  const SectionSpec* spec = find_child(*spec_, key);
  if (spec == nullptr) {
    throw std::logic_error("the configuration schema has no [" + name_ + "." + std::string(key) +
                           "]");
  }
  return checked(file_, node(key), name_ + "." + std::string(key), *spec);
}

ConfigFile ConfigFile::load(const std::string& path) {
  auto text = linux_os::read_file(path);
  if (!text) throw UsageError("config " + text.error().message);
  return parse(*text, path);
}

ConfigFile ConfigFile::parse(std::string_view text, const std::string& path) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw UsageError("config " + path + ":" + std::to_string(where.line) + ":" +
                     std::to_string(where.column) + ": " + std::string(e.description()));
  }
  ConfigFile file(path, std::move(root));
  try {
    file.migration_ = migrate_config(file.root_);
  } catch (const UsageError& e) {
    file.fail(e.what());
  }
  // Every top-level name is a table of the schema, or the file's own schema_version.
  const SectionSpec& top = schema_section("");
  for (const auto& [key, value] : file.root_) {
    if (find_key(top, key.str()) == nullptr && find_child(top, key.str()) == nullptr) {
      file.fail(line_of(value) + "unknown table or key '" + std::string(key.str()) + "'");
    }
  }
  return file;
}

ConfigSection ConfigFile::section(std::string_view name) const {
  return ConfigSection::checked(*this, root_.get(name), std::string(name), schema_section(name));
}

std::vector<ConfigSection> ConfigFile::section_array(std::string_view name) const {
  const SectionSpec& spec = schema_section(name);
  std::vector<ConfigSection> out;
  const toml::node* n = root_.get(name);
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  if (a == nullptr) fail("[[" + std::string(name) + "]] must be an array of tables");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string item = std::string(name) + "#" + std::to_string(i + 1);
    out.push_back(ConfigSection::checked(*this, a->get(i), item, spec));
  }
  return out;
}

void ConfigFile::fail(const std::string& what) const {
  throw UsageError("config " + path_ + ": " + what);
}

}  // namespace azt::app
