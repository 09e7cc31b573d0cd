#include "config/config_schema.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "config/config_migrations.hpp"
#include "config/schema_keys.hpp"

namespace azt::app {
namespace {

constexpr std::array<KeySpec, 1> kFileKeys{{
    {.key = "schema_version",
     .type = KeyType::Integer,
     .default_note = "0 when absent",
     .help = "the file's layout, 2 now. Older files are migrated in memory (0 → 1: `[station] "
             "height_m` → `alt_m`, both present is an error; 1 → 2: `[sim.az]` / `[sim.el]` "
             "`max_rate_deg_s` and `encoder_bits` move to `[mount.az]` / `[mount.el]`, and the "
             "motor model is copied there, `stiction_duty` as `min_duty`) and saved migrated by "
             "the next change, the original kept as `.bak`; newer versions are refused",
     .access = Access::ReadOnly},
}};

static_assert(kSchemaVersion == 2, "schema_version's help names the layout's version");

constexpr SectionSpec kFileSection{
    .name = "", .chapter = Chapter::File, .keys = kFileKeys, .title = "its layout"};

std::vector<SectionSpec> all_sections() {
  std::vector<SectionSpec> out{kFileSection};
  for (const auto group :
       {sky_sections(), control_sections(), target_sections(), schedule_sections(),
        hooks_sections(), antenna_sections(), hardware_sections(), station_io_sections(),
        server_sections(), service_sections(), radio_sections(), sim_sections()}) {
    out.insert(out.end(), group.begin(), group.end());
  }
  return out;
}

}  // namespace

std::span<const SectionSpec> config_sections() {
  static const std::vector<SectionSpec> sections = all_sections();
  return sections;
}

const SectionSpec* find_section(std::string_view name) {
  const auto sections = config_sections();
  const auto it = std::find_if(sections.begin(), sections.end(),
                               [name](const SectionSpec& s) { return s.name == name; });
  return it == sections.end() ? nullptr : &*it;
}

const KeySpec* find_key(const SectionSpec& section, std::string_view key) {
  const auto it = std::find_if(section.keys.begin(), section.keys.end(),
                               [key](const KeySpec& k) { return k.key == key; });
  return it == section.keys.end() ? nullptr : &*it;
}

const SectionSpec* find_child(const SectionSpec& section, std::string_view key) {
  // A quoted TOML key may hold a dot ("mount.az" = 1 at the top): never a table's name.
  if (key.empty() || key.find('.') != std::string_view::npos) return nullptr;
  if (section.name.empty()) return find_section(key);
  return find_section(std::string(section.name) + "." + std::string(key));
}

std::string_view type_name(KeyType type) {
  switch (type) {
    case KeyType::Boolean:
      return "boolean";
    case KeyType::Integer:
      return "integer";
    case KeyType::Number:
      return "number";
    case KeyType::Text:
      return "text";
    case KeyType::Choice:
      return "choice";
    case KeyType::GpioLine:
      return "gpio_line";
    case KeyType::TextList:
      return "text_list";
    case KeyType::NumberList:
      return "number_list";
    case KeyType::IntegerList:
      return "integer_list";
  }
  return "?";
}

std::string_view applies_name(Applies applies) {
  switch (applies) {
    case Applies::Live:
      return "live";
    case Applies::Restart:
      return "restart";
  }
  return "?";
}

std::string_view access_name(Access access) {
  switch (access) {
    case Access::Editable:
      return "editable";
    case Access::ReadOnly:
      return "read_only";
    case Access::Secret:
      return "secret";
  }
  return "?";
}

std::string_view chapter_title(Chapter chapter) {
  switch (chapter) {
    case Chapter::File:
      return "The file";
    case Chapter::Sky:
      return "Station, sky and atmosphere";
    case Chapter::Control:
      return "Control, travel, corrections and the mount";
    case Chapter::Targets:
      return "Targets";
    case Chapter::Antenna:
      return "The antenna";
    case Chapter::StationIo:
      return "Station I/O: E-stop, limit switches, PTT and the T/R sequencer";
    case Chapter::Servers:
      return "Servers for PC programs and the console";
    case Chapter::Services:
      return "GPS, time, the scan receiver and exports";
    case Chapter::Radio:
      return "The radio: Doppler to the rig, WSJT-X";
    case Chapter::Simulation:
      return "The simulated antenna";
  }
  return "?";
}

const toml::table* table_at(const toml::table& root, std::string_view name) {
  const toml::table* t = &root;
  while (t != nullptr && !name.empty()) {
    const auto dot = name.find('.');
    const toml::node* n = t->get(name.substr(0, dot));
    t = n != nullptr ? n->as_table() : nullptr;
    name = dot == std::string_view::npos ? std::string_view() : name.substr(dot + 1);
  }
  return t;
}

std::pair<std::string_view, std::string_view> parent_and_key(std::string_view name) {
  const auto dot = name.rfind('.');
  if (dot == std::string_view::npos) return {std::string_view(), name};
  return {name.substr(0, dot), name.substr(dot + 1)};
}

const toml::array* array_at(const toml::table& root, std::string_view name) {
  const auto [parent, key] = parent_and_key(name);
  const toml::table* t = table_at(root, parent);
  const toml::node* n = t != nullptr ? t->get(key) : nullptr;
  return n != nullptr ? n->as_array() : nullptr;
}

}  // namespace azt::app
