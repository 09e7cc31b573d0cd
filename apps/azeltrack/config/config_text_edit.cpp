#include "config/config_text_edit.hpp"
#include "config/toml_text.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

namespace azt::app {
namespace {

struct Edit {
  std::size_t begin = 0;  ///< byte offsets into the text
  std::size_t end = 0;
  std::string replacement;
};

/// Line and column (1-based, columns in code points, as toml++ counts them) to byte offsets.
class TextIndex {
 public:
  explicit TextIndex(const std::string& text) : text_(text) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] == '\n') line_starts_.push_back(i + 1);
    }
  }
  [[nodiscard]] std::optional<std::size_t> offset(const toml::source_position& p) const {
    if (p.line == 0 || p.line > line_starts_.size() || p.column == 0) return std::nullopt;
    std::size_t at = line_starts_[p.line - 1];
    for (toml::source_index col = 1; col < p.column; ++col) {
      if (at >= text_.size()) return std::nullopt;
      ++at;  // past the lead byte, then past continuation bytes
      while (at < text_.size() && (static_cast<unsigned char>(text_[at]) & 0xC0U) == 0x80U) ++at;
    }
    return at;
  }
  /// The offset just past line `line`'s newline (or the end of the text).
  [[nodiscard]] std::size_t after_line(toml::source_index line) const {
    return line < line_starts_.size() ? line_starts_[line] : text_.size();
  }
  [[nodiscard]] std::size_t line_start(toml::source_index line) const {
    return line_starts_[std::min<std::size_t>(line, line_starts_.size()) - 1];
  }

 private:
  const std::string& text_;
  std::vector<std::size_t> line_starts_;
};

bool same(const toml::node& a, const toml::node& b) {
  if (a.type() != b.type()) return false;
  switch (a.type()) {
    case toml::node_type::table:
      return *a.as_table() == *b.as_table();
    case toml::node_type::array:
      return *a.as_array() == *b.as_array();
    case toml::node_type::string:
      return *a.as_string() == *b.as_string();
    case toml::node_type::integer:
      return *a.as_integer() == *b.as_integer();
    case toml::node_type::floating_point:
      return *a.as_floating_point() == *b.as_floating_point();
    case toml::node_type::boolean:
      return *a.as_boolean() == *b.as_boolean();
    default:
      return false;  // dates and times: not in our files; rewrite the whole file
  }
}

bool is_array_of_tables(const toml::node& n) {
  const toml::array* a = n.as_array();
  return a != nullptr && !a->empty() && a->is_array_of_tables();
}

std::optional<std::string> new_tables_text(const std::string& name, const toml::node& value);

/// `header` ("[mount.az]", "[[serial]]") and its "key = value" lines, then its own tables under
/// their full names. A table that holds only tables needs no header of its own ([mount] for
/// [mount.az]); a table inside an item of an array of tables has no simple place.
std::optional<std::string> table_text(const std::string& header, const std::string& name,
                                      const toml::table& t) {
  std::string plain;
  std::string nested;
  for (const auto& [key, value] : t) {
    if (value.is_table() || is_array_of_tables(value)) {
      if (header.rfind("[[", 0) == 0) return std::nullopt;
      const auto sub = new_tables_text(name + "." + std::string(key.str()), value);
      if (!sub) return std::nullopt;
      nested += *sub;
    } else {
      plain += std::string(key.str()) + " = " + format_toml_value(value) + "\n";
    }
  }
  const bool own_header = !plain.empty() || nested.empty();
  return (own_header ? "\n" + header + "\n" + plain : std::string()) + nested;
}

/// A new table or array of tables named `name` (dotted: "mount.az"), as text for the file's end.
std::optional<std::string> new_tables_text(const std::string& name, const toml::node& value) {
  if (const toml::array* items = value.as_array()) {
    std::string out;
    for (const auto& item : *items) {
      const auto text = table_text("[[" + name + "]]", name, *item.as_table());
      if (!text) return std::nullopt;
      out += *text;
    }
    return out;
  }
  return table_text("[" + name + "]", name, *value.as_table());
}

class Differ {
 public:
  Differ(const std::string& text, std::vector<Edit>& edits)
      : text_(text), index_(text), edits_(edits) {}

  /// `path` is the table's dotted name ("" at the top); tables inside an item of an array of
  /// tables have none (`in_item`): nothing new can be named there.
  bool table(const toml::table& before, const toml::table& after, const std::string& path,
             bool in_item = false) {
    for (const auto& [key, value] : after) {
      const std::string name =
          path.empty() ? std::string(key.str()) : path + "." + std::string(key.str());
      const toml::node* old = before.get(key.str());
      if (old == nullptr) {
        if (!added(before, std::string(key.str()), name, value, path.empty() && !in_item,
                   in_item)) {
          return false;
        }
      } else if (!changed(*old, value, name, in_item)) {
        return false;
      }
    }
    for (const auto& [key, value] : before) {
      if (after.get(key.str()) == nullptr && !removed(key, value)) return false;
    }
    return true;
  }

 private:
  bool changed(const toml::node& old, const toml::node& now, const std::string& name,
               bool in_item) {
    if (same(old, now)) return true;
    if (old.is_table() && now.is_table()) {
      return table(*old.as_table(), *now.as_table(), name, in_item);
    }
    if (is_array_of_tables(old) && is_array_of_tables(now)) return items_changed(old, now, name);
    if (now.is_table() || is_array_of_tables(now) || is_array_of_tables(old)) return false;
    const auto begin = index_.offset(old.source().begin);
    const auto end = index_.offset(old.source().end);
    if (!begin || !end || *end < *begin) return false;
    edits_.push_back({*begin, *end, format_toml_value(now)});
    return true;
  }

  /// Items changed in place, and new ones after them: [[name]] tables at the file's end.
  bool items_changed(const toml::node& old, const toml::node& now, const std::string& name) {
    const toml::array& a = *old.as_array();
    const toml::array& b = *now.as_array();
    if (b.size() < a.size()) return false;
    for (std::size_t i = 0; i < b.size(); ++i) {
      const toml::table& item = *b.get(i)->as_table();
      if (i < a.size() && !table(*a.get(i)->as_table(), item, name, true)) return false;
      if (i < a.size()) continue;
      const auto text = table_text("[[" + name + "]]", name, item);
      if (!text) return false;
      edits_.push_back({text_.size(), text_.size(), *text});
    }
    return true;
  }

  bool added(const toml::table& parent, const std::string& key, const std::string& name,
             const toml::node& value, bool root, bool in_item) {
    if (value.is_table() || is_array_of_tables(value)) {
      // A new table, at any depth, goes at the end of the file under its full name.
      if (in_item || parent.is_inline()) return false;
      const auto text = new_tables_text(name, value);
      if (!text) return false;
      edits_.push_back({text_.size(), text_.size(), *text});
      return true;
    }
    // A new top-level plain key has no simple place.
    if (root || parent.is_inline()) return false;
    // After the last line of the table's own values (or its [header]).
    toml::source_index last = parent.source().begin.line;
    if (last == 0) return false;
    for (const auto& [k, v] : parent) {
      if (!v.is_table() && !is_array_of_tables(v)) last = std::max(last, v.source().end.line);
    }
    const std::size_t at = index_.after_line(last);
    const std::string newline = at > 0 && text_[at - 1] != '\n' ? "\n" : "";
    edits_.push_back({at, at, newline + key + " = " + format_toml_value(value) + "\n"});
    return true;
  }

  bool removed(const toml::key& key, const toml::node& value) {
    if (value.is_table() || is_array_of_tables(value)) return false;
    const auto first = key.source().begin.line;
    const auto last = value.source().end.line;
    if (first == 0 || last < first) return false;
    edits_.push_back({index_.line_start(first), index_.after_line(last), ""});
    return true;
  }

  const std::string& text_;
  TextIndex index_;
  std::vector<Edit>& edits_;
};

}  // namespace

std::string format_toml_value(const toml::node& value) { return toml_text(value); }

std::optional<std::string> edit_toml_text(const std::string& text, const toml::table& before,
                                          const toml::table& after) {
  std::vector<Edit> edits;
  if (!Differ(text, edits).table(before, after, "")) return std::nullopt;
  // From the end of the text backwards, so earlier offsets stay valid. Insertions at one place
  // are applied last-first, which leaves them in the order they were made.
  std::reverse(edits.begin(), edits.end());
  std::stable_sort(edits.begin(), edits.end(),
                   [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  std::string out = text;
  std::size_t limit = out.size();
  for (const Edit& e : edits) {
    if (e.end > limit) return std::nullopt;  // overlapping edits: not a simple change
    out.replace(e.begin, e.end - e.begin, e.replacement);
    limit = e.begin;
  }
  try {
    if (toml::parse(out) != after) return std::nullopt;
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
  return out;
}

}  // namespace azt::app
