#pragma once
// The configuration schema as JSON: `azeltrack config schema --json` and the console's
// GET /api/config/schema (docs/web-api.md), which adds each key's value in the running file.

#include <toml++/toml.h>

#include <nlohmann/json.hpp>

namespace azt::app {

/// {"schema_version", "sections": [{"name", "title", "help", "chapter", "array_of_tables",
/// "keys": [{"key", "type", "unit", "range", "items", "choices", "default", "default_note",
/// "help", "applies", "access"}]}]}. Sections that only hold child tables are left out.
const nlohmann::json& schema_json();

/// schema_json() with the values of `root`: each key of a table section gains "value" (null when
/// absent: the default applies), an array-of-tables section gains "items" (one object per
/// [[table]], its keys as in the file). A secret's value is never given.
nlohmann::json schema_json_with_values(const toml::table& root);

/// A TOML value as JSON: numbers, strings, booleans, arrays and tables; anything else is null.
nlohmann::json toml_to_json(const toml::node& node);

}  // namespace azt::app
