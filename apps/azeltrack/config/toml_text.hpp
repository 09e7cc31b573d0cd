#pragma once
// A TOML node as azeltrack writes it into a configuration file: strings double-quoted with their
// Unicode kept, tables indented, and every float in the shortest text that reads back to the same
// double. toml++ offers 17 digits (0.1 as 0.10000000000000001) or a "relaxed" 6 significant
// digits, which silently moved a saved station position by metres (46.1895779 became 46.1896):
// a saved setting must read back exactly what was saved.

#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace azt::app {

std::string toml_text(const toml::node& node);

/// Rewrites each float literal outside strings and comments in its shortest round-trip form.
std::string shortest_floats(std::string_view toml);

}  // namespace azt::app
