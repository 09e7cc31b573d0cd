#include "console/restart_needed.hpp"

#include <algorithm>
#include <optional>

#include "config/config_schema.hpp"
#include "config/toml_text.hpp"

namespace azt::app {
namespace {

/// The value's text, numbers of a number key as doubles: a default written "20" and a saved
/// 20.0 are the same setting.
std::string canonical(const KeySpec& k, const toml::node& n) {
  if (k.type == KeyType::Number && n.is_number()) {
    return toml_text(toml::value<double>(*n.value<double>()));
  }
  if (k.type == KeyType::NumberList && n.is_array()) {
    toml::array doubles;
    for (const auto& item : *n.as_array()) doubles.push_back(item.value_or(0.0));
    return toml_text(doubles);
  }
  return toml_text(n);
}

/// The key's value as it takes effect: the file's, else the default; nullopt when neither.
std::optional<std::string> effective(const KeySpec& k, const toml::table* table) {
  if (const toml::node* n = table != nullptr ? table->get(k.key) : nullptr) return canonical(k, *n);
  if (k.default_toml.empty()) return std::nullopt;
  const toml::table parsed = toml::parse("v = " + std::string(k.default_toml));
  return canonical(k, *parsed.get("v"));
}

bool same(const KeySpec& k, const toml::table* a, const toml::table* b) {
  return effective(k, a) == effective(k, b);
}

bool watched(const KeySpec& k) {
  return k.applies == Applies::Restart && k.access == Access::Editable;
}

void compare_table(const SectionSpec& s, const std::string& prefix, const toml::table* a,
                   const toml::table* b, std::vector<std::string>& out) {
  for (const KeySpec& k : s.keys) {
    if (watched(k) && !same(k, a, b)) out.push_back(prefix + std::string(k.key));
  }
}

const toml::table* item_at(const toml::array* a, std::size_t i) {
  return a != nullptr && i < a->size() ? a->get(i)->as_table() : nullptr;
}

}  // namespace

std::vector<std::string> restart_needed(const toml::table& started, const toml::table& saved) {
  std::vector<std::string> out;
  for (const SectionSpec& s : config_sections()) {
    if (s.name.empty() || s.keys.empty()) continue;
    const std::string name(s.name);
    if (!s.array_of_tables) {
      compare_table(s, name + ".", table_at(started, s.name), table_at(saved, s.name), out);
      continue;
    }
    const toml::array* a = array_at(started, s.name);
    const toml::array* b = array_at(saved, s.name);
    const std::size_t n = std::max(a != nullptr ? a->size() : 0, b != nullptr ? b->size() : 0);
    for (std::size_t i = 0; i < n; ++i) {
      compare_table(s, name + "." + std::to_string(i + 1) + ".", item_at(a, i), item_at(b, i), out);
    }
  }
  return out;
}

}  // namespace azt::app
