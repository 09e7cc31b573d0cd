#pragma once
// Runtime saves that keep a hand-written configuration file as its author wrote it: comments,
// order, blank lines. Only the text of values that changed is replaced, new keys get a line of
// their own in their table, removed keys lose their line.

#include <toml++/toml.h>

#include <functional>
#include <optional>
#include <string>

namespace azt::app {

/// The formatting of values written into a file (also used for whole-file saves).
std::string format_toml_value(const toml::node& value);

/// `text` (which parses to `before`, with its source positions) edited so that it parses to
/// `after`. nullopt when the change is not one of the simple kinds (a value changed, a key added
/// to or removed from a table written with a [header], a table added at any depth ([mount.az],
/// written at the end), an item of an array of tables changed in place or added after the others):
/// the caller then writes the whole file. The result is checked: it parses, and to a table equal
/// to `after`.
std::optional<std::string> edit_toml_text(const std::string& text, const toml::table& before,
                                          const toml::table& after);

}  // namespace azt::app
