#include "config/config_file.hpp"

#include <algorithm>
#include <cmath>

#include "azt/linux/atomic_file.hpp"
#include "common/usage_error.hpp"

namespace azt::app {
namespace {

bool allowed_key(std::string_view key, std::initializer_list<std::string_view> allowed) {
  return std::find(allowed.begin(), allowed.end(), key) != allowed.end();
}

const toml::table* checked_table(const ConfigFile& file, const toml::node* node,
                                 const std::string& name,
                                 std::initializer_list<std::string_view> allowed) {
  if (node == nullptr) return nullptr;
  const toml::table* t = node->as_table();
  if (t == nullptr) file.fail("[" + name + "] must be a table");
  for (const auto& [key, value] : *t) {
    if (!allowed_key(key.str(), allowed)) {
      file.fail("unknown key [" + name + "]." + std::string(key.str()));
    }
  }
  return t;
}

}  // namespace

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
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  auto v = n->value<double>();  // integers too
  if (!v || !std::isfinite(*v)) fail(key, "must be a finite number");
  return v;
}

std::optional<std::int64_t> ConfigSection::integer(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_integer()) fail(key, "must be an integer");
  return n->value<std::int64_t>();
}

std::optional<std::string> ConfigSection::text(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  auto v = n->value<std::string>();
  if (!v) fail(key, "must be a string");
  return v;
}

std::optional<bool> ConfigSection::boolean(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_boolean()) fail(key, "must be true or false");
  return n->value<bool>();
}

const toml::array* ConfigSection::array(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return nullptr;
  if (!n->is_array()) fail(key, "must be an array");
  return n->as_array();
}

ConfigSection ConfigSection::child(std::string_view key,
                                   std::initializer_list<std::string_view> allowed) const {
  const std::string name = name_ + "." + std::string(key);
  return ConfigSection(file_, checked_table(file_, node(key), name, allowed), name);
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
  for (const auto& [key, value] : file.root_) {
    if (!allowed_key(key.str(), {"schema_version",
                                 "station",
                                 "sky",
                                 "atmosphere",
                                 "control",
                                 "geometry",
                                 "corrections",
                                 "park",
                                 "mount",
                                 "sim",
                                 "target",
                                 "antenna",
                                 "hamlib",
                                 "hub",
                                 "pwm",
                                 "rotctld",
                                 "serial",
                                 "pstrotator",
                                 "web",
                                 "sequencer",
                                 "gpio",
                                 "hardware",
                                 "satellites",
                                 "spacecraft",
                                 "log",
                                 "gps",
                                 "time",
                                 "export",
                                 "pointing",
                                 "receiver"})) {
      file.fail("unknown table or key '" + std::string(key.str()) + "'");
    }
  }
  return file;
}

ConfigSection ConfigFile::section(std::string_view name,
                                  std::initializer_list<std::string_view> allowed) const {
  const std::string n(name);
  return ConfigSection(*this, checked_table(*this, root_.get(name), n, allowed), n);
}

std::vector<ConfigSection> ConfigFile::section_array(
    std::string_view name, std::initializer_list<std::string_view> allowed) const {
  std::vector<ConfigSection> out;
  const toml::node* n = root_.get(name);
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  if (a == nullptr) fail("[[" + std::string(name) + "]] must be an array of tables");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const std::string item = std::string(name) + "#" + std::to_string(i + 1);
    out.emplace_back(*this, checked_table(*this, a->get(i), item, allowed), item);
  }
  return out;
}

void ConfigFile::fail(const std::string& what) const {
  throw UsageError("config " + path_ + ": " + what);
}

}  // namespace azt::app
