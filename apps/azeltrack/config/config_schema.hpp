#pragma once
// The one description of every configuration key: its type, unit, range, default, help text and
// whether the running daemon applies it at once. The loader checks the file against it
// (config_file.cpp), the console's settings are checked and listed from it (GET
// /api/config/schema, PUT /api/config/SECTION) and docs/configuration.md's reference is printed
// from it (`azeltrack config schema --markdown`), so the four cannot disagree.
//
// The key tables are split by concern: schema_sky_keys.cpp, schema_control_keys.cpp,
// schema_target_keys.cpp, schema_antenna_keys.cpp, schema_station_io_keys.cpp,
// schema_server_keys.cpp, schema_service_keys.cpp, schema_radio_keys.cpp, schema_hooks_keys.cpp
// and schema_sim_keys.cpp.

#include <toml++/toml.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace azt::app {

/// What a key holds. A number accepts integers too; a GPIO line is a line number on [gpio] chip
/// or "CHIP:N"; lists are TOML arrays of one kind.
enum class KeyType {
  Boolean,
  Integer,
  Number,
  Text,
  Choice,
  GpioLine,
  TextList,
  NumberList,
  IntegerList
};

/// When a saved change takes effect in a running daemon.
enum class Applies { Live, Restart };

/// Who may read and change a key through the console. A secret (a password's hash, a token's
/// digest) is never returned and never changed by the generic settings endpoint; a read-only key
/// belongs to the program (the file's layout version).
enum class Access { Editable, ReadOnly, Secret };

/// The reference's chapters, in the order docs/configuration.md shows them.
enum class Chapter {
  File,
  Sky,
  Control,
  Targets,
  Antenna,
  StationIo,
  Servers,
  Services,
  Radio,
  Simulation
};

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// The values a number, an integer or a list's items may take; an infinite end is open.
struct Range {
  double min = -kUnbounded;
  double max = kUnbounded;
  bool min_exclusive = false;
  bool max_exclusive = false;
};

constexpr Range closed(double min, double max) { return {min, max, false, false}; }
constexpr Range within(double magnitude) { return {-magnitude, magnitude, false, false}; }
constexpr Range above_up_to(double min, double max) { return {min, max, true, false}; }
constexpr Range from_below(double min, double max) { return {min, max, false, true}; }
constexpr Range above(double min) { return {min, kUnbounded, true, false}; }
constexpr Range at_least(double min) { return {min, kUnbounded, false, false}; }

/// How many items a list holds; 0 as max means no limit.
struct ItemCount {
  std::size_t min = 0;
  std::size_t max = 0;
};

struct KeySpec {
  std::string_view key;
  KeyType type = KeyType::Text;
  std::string_view unit;  ///< "°", "s", "Hz", "m", … ("" for none)
  Range range;            ///< numbers and integers; a list's items
  ItemCount items;        ///< lists
  /// The names a choice may take; for an integer, the values it may take, as text.
  std::span<const std::string_view> choices;
  std::string_view default_toml;  ///< a TOML value; "" when there is none or it depends
  std::string_view default_note;  ///< what applies when absent and default_toml cannot say it
  std::string_view help;          ///< Markdown: `code` and [links](page.md), relative to docs/
  Applies applies = Applies::Restart;
  Access access = Access::Editable;
  /// A text list that also takes one string alone, as a list of one: a program to run, with
  /// or without its arguments (`[hooks] aos`).
  bool text_alone = false;
};

struct SectionSpec {
  std::string_view name;  ///< "control", "mount.az", "serial"; "" for the file's top level
  Chapter chapter = Chapter::File;
  bool array_of_tables = false;  ///< [[serial]], [[park]], [[spacecraft]]
  std::span<const KeySpec> keys;
  std::string_view title;
  std::string_view help;  ///< Markdown, shown above the section's keys
};

/// Every section, top level first, in the reference's order. Sections that only hold child
/// tables ("mount" holds "mount.az" and "mount.el") have no keys.
std::span<const SectionSpec> config_sections();
/// The section named `name` ("mount.az"), or null.
const SectionSpec* find_section(std::string_view name);
/// The key `key` of `section`, or null.
const KeySpec* find_key(const SectionSpec& section, std::string_view key);
/// The child table `key` of `section` ("az" of "mount"), or null.
const SectionSpec* find_child(const SectionSpec& section, std::string_view key);
/// The table a dotted section name ("mount.az") names in a file's `root`, or null.
const toml::table* table_at(const toml::table& root, std::string_view name);
/// The array of tables a dotted section name names in `root`, or null: "serial" at the top,
/// "satellites.transmitter" inside [satellites] (never a top-level key spelled with a dot).
const toml::array* array_at(const toml::table& root, std::string_view name);
/// A dotted section name split at its last dot: ("satellites", "transmitter"), ("", "serial").
std::pair<std::string_view, std::string_view> parent_and_key(std::string_view name);

/// Why `value` cannot be `spec`'s value ("must be 0 to 2", "must be an integer"), or nullopt.
std::optional<std::string> key_violation(const KeySpec& spec, const toml::node& value);
/// The range in words: "0 to 2", "above 0 and at most 1", "within ±10"; "" when unbounded.
std::string range_text(const Range& range);
/// "\"hold\" or \"park\"": the choices as the error that lists them says them.
std::string choices_text(const KeySpec& spec);

std::string_view type_name(KeyType type);
std::string_view applies_name(Applies applies);
std::string_view access_name(Access access);
std::string_view chapter_title(Chapter chapter);

}  // namespace azt::app
