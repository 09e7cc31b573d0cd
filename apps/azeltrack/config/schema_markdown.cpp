#include "config/schema_markdown.hpp"

#include <optional>
#include <sstream>

#include "config/config_schema.hpp"

namespace azt::app {
namespace {

/// Text for a table cell: a '|' would end the cell.
std::string cell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string code_list(const KeySpec& k) {
  std::string out;
  for (std::size_t i = 0; i < k.choices.size(); ++i) {
    if (i > 0) out += i + 1 == k.choices.size() ? " or " : ", ";
    out += "`" + std::string(k.choices[i]) + "`";
  }
  return out;
}

/// "number (°)", "list of numbers (°)": the kind of value, with its unit.
std::string kind_words(const KeySpec& k) {
  std::string kind;
  switch (k.type) {
    case KeyType::Boolean:
      return "`true` or `false`";
    case KeyType::Choice:
      return code_list(k);
    case KeyType::GpioLine:
      return "GPIO line: 0 to 1023, or `\"CHIP:N\"`";
    case KeyType::Integer:
      kind = "integer";
      break;
    case KeyType::Number:
      kind = "number";
      break;
    case KeyType::Text:
      kind = "text";
      break;
    case KeyType::TextList:
      kind = k.text_alone ? "text, or list of text" : "list of text";
      break;
    case KeyType::NumberList:
      kind = "list of numbers";
      break;
    case KeyType::IntegerList:
      kind = "list of integers";
      break;
  }
  if (!k.unit.empty()) kind += " (" + std::string(k.unit) + ")";
  return kind;
}

std::optional<std::string> count_words(const ItemCount& c) {
  if (c.min == 0 && c.max == 0) return std::nullopt;
  if (c.min == c.max) return "exactly " + std::to_string(c.min);
  if (c.min == 0) return "at most " + std::to_string(c.max);
  if (c.max == 0) return "at least " + std::to_string(c.min);
  return std::to_string(c.min) + " to " + std::to_string(c.max);
}

/// The value column: the kind, then its count, range or choices.
std::string value_words(const KeySpec& k) {
  std::string out = kind_words(k);
  if (const auto count = count_words(k.items)) out += ", " + *count;
  const std::string range = range_text(k.range);
  if (!range.empty()) out += (k.items.max > 0 || k.items.min > 0) ? ", each " : ": ";
  out += range;
  if (k.type == KeyType::Integer && !k.choices.empty()) out += ": " + choices_text(k);
  return out;
}

std::string default_words(const KeySpec& k) {
  if (!k.default_toml.empty()) return "`" + std::string(k.default_toml) + "`";
  if (!k.default_note.empty()) return std::string(k.default_note);
  return "—";
}

std::string applies_words(const KeySpec& k) {
  std::string out = k.applies == Applies::Live ? "at once" : "restart";
  switch (k.access) {
    case Access::Editable:
      break;
    case Access::ReadOnly:
      out += "; set by the program";
      break;
    case Access::Secret:
      out += "; secret: never shown or set by the console";
      break;
  }
  return out;
}

void write_keys(std::ostream& out, std::span<const KeySpec> keys) {
  out << "| key | value | default | applies | meaning |\n| --- | --- | --- | --- | --- |\n";
  for (const KeySpec& k : keys) {
    out << "| `" << k.key << "` | " << cell(value_words(k)) << " | " << cell(default_words(k))
        << " | " << applies_words(k) << " | " << cell(k.help) << " |\n";
  }
}

/// "`[mount.az]`", "`[[park]]`", "the file's top level".
std::string heading_name(const SectionSpec& s) {
  if (s.name.empty()) return "The file's top level";
  return s.array_of_tables ? "`[[" + std::string(s.name) + "]]`"
                           : "`[" + std::string(s.name) + "]`";
}

/// One section, or several that share their keys ([hardware.az], [hardware.el]): their heading,
/// help and table. Returns how many sections it wrote.
std::size_t write_sections(std::ostream& out, std::span<const SectionSpec> rest) {
  const SectionSpec& first = rest.front();
  std::size_t n = 1;
  while (n < rest.size() && rest[n].keys.data() == first.keys.data()) ++n;
  out << "#### ";
  for (std::size_t i = 0; i < n; ++i) out << (i > 0 ? ", " : "") << heading_name(rest[i]);
  out << (n == 1 ? ": " + std::string(first.title) : std::string()) << "\n\n";
  if (!first.help.empty()) out << first.help << "\n\n";
  write_keys(out, first.keys);
  out << "\n";
  return n;
}

constexpr std::string_view kIntroduction =
    "## Keys\n\n"
    "Generated from the program's schema, which the loader checks every file against and the "
    "console's settings come from (`GET /api/config/schema`, docs/web-api.md). \"Applies\" says "
    "when a saved change takes effect in a running daemon: `at once`, or at the next start "
    "(`restart`; the console lists such keys in `restart_needed`). A default in `code` is the "
    "TOML value used when the key is absent; \"—\" means none: the key must be given where it is "
    "needed. Ranges are inclusive unless they say \"above\" or \"below\".\n\n";

}  // namespace

std::string schema_markdown() {
  std::ostringstream out;
  out << kIntroduction;
  const auto sections = config_sections();
  std::optional<Chapter> chapter;
  for (std::size_t i = 0; i < sections.size();) {
    if (sections[i].keys.empty()) {  // only child tables: shown as those
      ++i;
      continue;
    }
    if (chapter != sections[i].chapter) {
      chapter = sections[i].chapter;
      out << "### " << chapter_title(*chapter) << "\n\n";
    }
    i += write_sections(out, sections.subspan(i));
  }
  std::string text = out.str();
  text.pop_back();  // one newline at the end, not two
  return text;
}

}  // namespace azt::app
