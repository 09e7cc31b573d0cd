// SatNOGS DB's TLE JSON to TLE text (satnogs_tle_json.hpp).
#include "satellites/satnogs_tle_json.hpp"

#include <nlohmann/json.hpp>

namespace azt::app {
namespace {

std::string line_of(const nlohmann::json& object, const char* key) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_string()) return "(no " + std::string(key) + ")";
  std::string line = it->get<std::string>();
  // One set is three lines: a line break inside a field would shift every line after it.
  for (char& c : line) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return line;
}

}  // namespace

std::optional<std::string> satnogs_tle_text(std::string_view text) {
  const nlohmann::json document = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
  if (!document.is_array() || document.empty() || !document.front().is_object() ||
      !document.front().contains("tle1")) {
    return std::nullopt;
  }
  std::string out;
  for (const nlohmann::json& entry : document) {
    if (!entry.is_object()) {
      out += "(not an object)\n(no tle1)\n(no tle2)\n";
      continue;
    }
    out += line_of(entry, "tle0") + "\n" + line_of(entry, "tle1") + "\n" + line_of(entry, "tle2") +
           "\n";
  }
  return out;
}

}  // namespace azt::app
