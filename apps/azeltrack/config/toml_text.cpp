#include "config/toml_text.hpp"

#include <charconv>
#include <regex>
#include <sstream>

namespace azt::app {
namespace {

constexpr toml::format_flags kFormat =
    toml::format_flags::allow_unicode_strings | toml::format_flags::indentation;

bool is_word_char(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' ||
         c == '-' || c == '+' || c == '.' || c == ':';
}

/// The word's shortest round-trip text when it is a float literal, else the word unchanged.
std::string shortest_float(const std::string& word) {
  static const std::regex float_literal(R"([+-]?[0-9]+(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  if (word.find_first_of(".eE") == std::string::npos || !std::regex_match(word, float_literal)) {
    return word;
  }
  double value = 0.0;
  const char* begin = word.data() + (word.front() == '+' ? 1 : 0);
  if (std::from_chars(begin, word.data() + word.size(), value).ec != std::errc{}) return word;
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, value);
  std::string out(buffer, r.ptr);
  if (out.find_first_of(".eEn") == std::string::npos) out += ".0";  // still a float
  return out;
}

/// Copies a string literal starting at `i` (its quote) through its end; returns the index after.
std::size_t copy_string(std::string_view t, std::size_t i, std::string& out) {
  const char quote = t[i];
  const bool triple = t.substr(i, 3) == std::string(std::size_t{3}, quote);
  const std::string_view end = triple ? std::string_view(quote == '"' ? "\"\"\"" : "'''")
                                      : std::string_view(quote == '"' ? "\"" : "'");
  std::size_t j = i + end.size();
  while (j < t.size() && t.substr(j, end.size()) != end) {
    const bool escaped = quote == '"' && t[j] == '\\' && j + 1 < t.size();
    j += escaped ? 2U : 1U;
  }
  j = std::min(t.size(), j + end.size());
  out.append(t.substr(i, j - i));
  return j;
}

}  // namespace

std::string shortest_floats(std::string_view t) {
  std::string out;
  out.reserve(t.size());
  std::size_t i = 0;
  while (i < t.size()) {
    const char c = t[i];
    if (c == '"' || c == '\'') {
      i = copy_string(t, i, out);
    } else if (c == '#') {
      const std::size_t eol = std::min(t.size(), t.find('\n', i));
      out.append(t.substr(i, eol - i));
      i = eol;
    } else if (is_word_char(c)) {
      std::size_t j = i;
      while (j < t.size() && is_word_char(t[j])) ++j;
      out += shortest_float(std::string(t.substr(i, j - i)));
      i = j;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

std::string toml_text(const toml::node& node) {
  std::ostringstream out;
  node.visit([&out](const auto& v) { out << toml::toml_formatter(v, kFormat); });
  return shortest_floats(out.str());
}

}  // namespace azt::app
