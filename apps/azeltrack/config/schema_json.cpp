#include "config/schema_json.hpp"

#include <cmath>
#include <string>

#include "config/config_migrations.hpp"
#include "config/config_schema.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

/// {"min", "max", "min_exclusive", "max_exclusive", "text"}; an open end is left out.
json range_json(const Range& r) {
  const std::string text = range_text(r);
  if (text.empty()) return nullptr;
  json out{{"min_exclusive", r.min_exclusive}, {"max_exclusive", r.max_exclusive}, {"text", text}};
  if (std::isfinite(r.min)) out["min"] = r.min;
  if (std::isfinite(r.max)) out["max"] = r.max;
  return out;
}

bool is_list(KeyType type) {
  switch (type) {
    case KeyType::TextList:
    case KeyType::NumberList:
    case KeyType::IntegerList:
      return true;
    case KeyType::Boolean:
    case KeyType::Integer:
    case KeyType::Number:
    case KeyType::Text:
    case KeyType::Choice:
    case KeyType::GpioLine:
      return false;
  }
  return false;
}

/// An integer's choices are numbers in JSON, as its values are.
json choices_json(const KeySpec& k) {
  json out = json::array();
  for (const auto& c : k.choices) {
    if (k.type == KeyType::Integer) {
      out.push_back(std::stoll(std::string(c)));
    } else {
      out.push_back(c);
    }
  }
  return out;
}

json default_json(const KeySpec& k) {
  if (k.default_toml.empty()) return nullptr;
  const toml::table parsed = toml::parse("value = " + std::string(k.default_toml));
  return toml_to_json(*parsed.get("value"));
}

json key_json(const KeySpec& k) {
  json items = nullptr;
  if (is_list(k.type)) {
    items = {{"min", k.items.min}, {"max", k.items.max == 0 ? json(nullptr) : json(k.items.max)}};
  }
  return {{"key", k.key},
          {"type", type_name(k.type)},
          {"unit", k.unit},
          {"range", range_json(k.range)},
          {"items", items},
          {"choices", choices_json(k)},
          {"default", default_json(k)},
          {"default_note", k.default_note},
          {"help", k.help},
          {"applies", applies_name(k.applies)},
          {"access", access_name(k.access)}};
}

json section_json(const SectionSpec& s) {
  json keys = json::array();
  for (const KeySpec& k : s.keys) keys.push_back(key_json(k));
  return {{"name", s.name},
          {"title", s.title},
          {"help", s.help},
          {"chapter", chapter_title(s.chapter)},
          {"array_of_tables", s.array_of_tables},
          {"keys", keys}};
}

json build_schema_json() {
  json sections = json::array();
  for (const SectionSpec& s : config_sections()) {
    if (!s.name.empty() && !s.keys.empty()) sections.push_back(section_json(s));
  }
  return {{"schema_version", kSchemaVersion}, {"sections", sections}};
}

/// The keys of one table as the file has them, secrets left out.
json values_of(const SectionSpec& spec, const toml::table* table) {
  json out = json::object();
  for (const KeySpec& k : spec.keys) {
    const toml::node* n = table != nullptr ? table->get(k.key) : nullptr;
    if (k.access != Access::Secret && n != nullptr) out[std::string(k.key)] = toml_to_json(*n);
  }
  return out;
}

void add_items(json& section, const SectionSpec& spec, const toml::table& root) {
  json items = json::array();
  if (const toml::array* a = array_at(root, spec.name)) {
    for (const auto& item : *a) items.push_back(values_of(spec, item.as_table()));
  }
  section["items"] = items;
}

void add_values(json& section, const SectionSpec& spec, const toml::table& root) {
  const json values = values_of(spec, table_at(root, spec.name));
  for (json& key : section["keys"]) {
    const std::string name = key["key"].get<std::string>();
    key["value"] = values.contains(name) ? values[name] : json(nullptr);
  }
}

}  // namespace

const json& schema_json() {
  static const json schema = build_schema_json();
  return schema;
}

json schema_json_with_values(const toml::table& root) {
  json out = schema_json();
  for (json& section : out["sections"]) {
    const SectionSpec* spec = find_section(section["name"].get<std::string>());
    if (spec == nullptr) continue;
    if (spec->array_of_tables) {
      add_items(section, *spec, root);
    } else {
      add_values(section, *spec, root);
    }
  }
  return out;
}

json toml_to_json(const toml::node& node) {
  if (const auto* b = node.as_boolean()) return b->get();
  if (const auto* i = node.as_integer()) return i->get();
  if (const auto* d = node.as_floating_point()) return d->get();
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* a = node.as_array()) {
    json out = json::array();
    for (const auto& item : *a) out.push_back(toml_to_json(item));
    return out;
  }
  if (const auto* t = node.as_table()) {
    json out = json::object();
    for (const auto& [key, value] : *t) out[std::string(key.str())] = toml_to_json(value);
    return out;
  }
  return nullptr;
}

}  // namespace azt::app
