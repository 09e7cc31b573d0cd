#include "console/settings_change.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "common/usage_error.hpp"
#include "console/console_model.hpp"

namespace azt::app {
namespace {

using json = nlohmann::json;

/// "park/2" -> ("park", 2); "control" -> ("control", 0); a bad number -> item max (no such item).
std::pair<std::string_view, std::size_t> split_route(std::string_view route) {
  const auto slash = route.find('/');
  if (slash == std::string_view::npos) return {route, 0};
  const std::string_view number = route.substr(slash + 1);
  const bool digits = !number.empty() && number.size() <= 3 &&
                      number.find_first_not_of("0123456789") == std::string_view::npos;
  const std::size_t item = digits ? std::stoul(std::string(number)) : 0;
  return {route.substr(0, slash), item > 0 ? item : std::numeric_limits<std::size_t>::max()};
}

const SectionSpec& section_of(std::string_view route, std::size_t item) {
  const std::string_view name = split_route(route).first;
  const SectionSpec* s = name.empty() ? nullptr : find_section(name);
  if (s == nullptr || s->keys.empty()) {
    throw ApiError(404, "", "no settings section [" + std::string(name) + "]");
  }
  if (item == std::numeric_limits<std::size_t>::max() || (item > 0 && !s->array_of_tables)) {
    throw ApiError(404, "", "no settings at /api/config/" + std::string(route));
  }
  if (item == 0 && s->array_of_tables) {
    throw ApiError(400, "",
                   "[[" + std::string(name) + "]] items are changed at /api/config/" +
                       std::string(name) + "/N, N from 1");
  }
  return *s;
}

/// A number of a list or a number key as TOML: a double, so that 1 and 1.0 read back alike.
toml::array array_of(const json& items, KeyType type) {
  toml::array out;
  for (const auto& v : items) {
    if (v.is_string()) {
      out.push_back(v.get<std::string>());
    } else if (v.is_boolean()) {
      out.push_back(v.get<bool>());
    } else if (v.is_number_integer() && type != KeyType::NumberList) {
      out.push_back(v.get<std::int64_t>());
    } else if (v.is_number()) {
      out.push_back(v.get<double>());
    } else {
      out.push_back(toml::table{});  // an object or a nested list: the check refuses it
    }
  }
  return out;
}

/// `value` as the TOML the key's type reads; what cannot be said in TOML (an object) becomes an
/// empty table, which every key's check refuses in its own words.
void put(toml::table& into, const KeySpec& k, const json& value) {
  const std::string key(k.key);
  if (value.is_boolean()) {
    into.insert_or_assign(key, value.get<bool>());
  } else if (value.is_string()) {
    into.insert_or_assign(key, value.get<std::string>());
  } else if (value.is_number_integer() && k.type != KeyType::Number &&
             !(value.is_number_unsigned() &&
               value.get<std::uint64_t>() >
                   static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))) {
    into.insert_or_assign(key, value.get<std::int64_t>());
  } else if (value.is_number()) {
    into.insert_or_assign(key, value.get<double>());
  } else if (value.is_array()) {
    into.insert_or_assign(key, array_of(value, k.type));
  } else {
    into.insert_or_assign(key, toml::table{});
  }
}

const KeySpec& checked_key(const SettingsChange& c, const std::string& key) {
  const KeySpec* k = find_key(*c.section, key);
  if (k == nullptr) throw ApiError(400, key, "unknown key " + c.table_name() + "." + key);
  if (k->access == Access::Secret) {
    throw ApiError(400, key,
                   c.table_name() + "." + key +
                       " is secret: it is set with `azeltrack web password` or `web token`");
  }
  if (k->access == Access::ReadOnly) {
    throw ApiError(400, key, c.table_name() + "." + key + " is set by the program");
  }
  return *k;
}

/// The table the change writes into, created on the way when absent.
toml::table& table_for(toml::table& root, std::string_view dotted) {
  toml::table* t = &root;
  while (!dotted.empty()) {
    const auto dot = dotted.find('.');
    const std::string part(dotted.substr(0, dot));
    if (!t->contains(part)) t->insert(part, toml::table{});
    t = (*t)[part].as_table();
    if (t == nullptr) throw UsageError("[" + part + "] is not a table in the file");
    dotted = dot == std::string_view::npos ? std::string_view() : dotted.substr(dot + 1);
  }
  return *t;
}

/// Item `item` (from 1) of the array of tables `name`, which may stand inside a table
/// ([[satellites.transmitter]] in [satellites]); the next item is added.
toml::table& item_for(toml::table& root, std::string_view name, std::size_t item,
                      const ItemFiller& fill) {
  const std::string key(name);
  const auto [parent_name, last] = parent_and_key(name);
  toml::table& parent = table_for(root, parent_name);
  if (!parent.contains(last)) parent.insert(last, toml::array{});
  toml::array* a = parent[last].as_array();
  if (a == nullptr) throw UsageError("[[" + key + "]] is not an array of tables in the file");
  while (fill && a->size() + 1 < item) a->push_back(fill(a->size()));
  if (item > a->size() + 1) {
    throw UsageError("[[" + key + "]] has " + std::to_string(a->size()) + " item(s): the next is " +
                     key + "/" + std::to_string(a->size() + 1));
  }
  if (item == a->size() + 1) a->push_back(toml::table{});
  toml::table* t = a->get(item - 1)->as_table();
  if (t == nullptr) throw UsageError(key + " item " + std::to_string(item) + " is not a table");
  return *t;
}

/// One of the station's grid and position is derived from the other (sky_config.cpp): the one
/// not given goes, or the file would hold two places that disagree.
void keep_station_consistent(const SettingsChange& c, toml::table& station) {
  if (c.section->name != "station") return;
  const bool grid = c.values.contains("grid");
  const bool position = c.values.contains("lat_deg") || c.values.contains("lon_deg");
  if (grid && !position) {
    station.erase("lat_deg");
    station.erase("lon_deg");
  }
  if (position && !grid) station.erase("grid");
}

}  // namespace

std::optional<LiveApply> live_apply_of(std::string_view section, std::string_view key) {
  // The station's place applies at once; its dish (dish_m, efficiency: the calibration's source
  // estimates) is read at start.
  if (section == "station" && key != "dish_m" && key != "efficiency") return LiveApply::Station;
  if (section == "sky" && key == "band") return LiveApply::Band;
  if (section == "sky" && key == "dx_grid") return LiveApply::DxGrid;
  // The pointing model is part of the corrections the antenna is handed whole.
  if (section == "corrections" || section == "pointing") return LiveApply::Corrections;
  if (section == "park") return LiveApply::Park;
  if (section == "schedule") return LiveApply::Schedule;
  if (section == "pol") return LiveApply::Pol;  // the follower takes the modes at its next tick
  return std::nullopt;
}

std::string SettingsChange::dotted(const KeySpec& key) const {
  std::string out(section->name);
  if (item > 0) out += "." + std::to_string(item);
  return out + "." + std::string(key.key);
}

std::string SettingsChange::table_name() const {
  if (item > 0) return "[" + std::string(section->name) + "#" + std::to_string(item) + "]";
  return "[" + std::string(section->name) + "]";
}

SettingsChange settings_change(std::string_view route, const json& body) {
  SettingsChange c;
  c.item = split_route(route).second;
  c.section = &section_of(route, c.item);
  if (!body.is_object() || body.empty()) {
    throw ApiError(400, "", "give the keys to change as a JSON object: {\"key\": value, …}");
  }
  for (const auto& [key, value] : body.items()) {
    const KeySpec& k = checked_key(c, key);
    c.keys.push_back(&k);
    if (value.is_null()) {
      c.removed.push_back(key);
      continue;
    }
    put(c.values, k, value);
    if (auto why = key_violation(k, *c.values.get(key))) {
      throw ApiError(400, key, c.table_name() + "." + key + " " + *why);
    }
  }
  return c;
}

ConfigStore::Change store_change(const SettingsChange& change, ItemFiller fill) {
  return [change, fill = std::move(fill)](toml::table& root) {
    toml::table& t = change.item > 0 ? item_for(root, change.section->name, change.item, fill)
                                     : table_for(root, change.section->name);
    for (const auto& [key, value] : change.values) t.insert_or_assign(key, value);
    for (const auto& key : change.removed) t.erase(key);
    keep_station_consistent(change, t);
  };
}

}  // namespace azt::app
