// OMM as CelesTrak's FORMAT=csv: a header row of OMM keywords, then one row per object. Fields
// follow RFC 4180 (a field in double quotes may hold commas, "" is a quote), one row per line.

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/orbit/omm_record.hpp"

namespace azt::orbit {

namespace {

/// The fields of one line, or nothing when a quoted field is not closed on it.
std::optional<std::vector<std::string>> split_csv(std::string_view line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        fields.back() += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) return std::nullopt;
  return fields;
}

OmmRecord read_row(std::string_view line, int number, const std::vector<std::string>& header) {
  OmmRecord record;
  record.line = number;
  const std::string where = "line " + std::to_string(number) + ": ";
  const std::optional<std::vector<std::string>> fields = split_csv(line);
  if (!fields) {
    record.problem = where + "a quoted field without its closing quote";
  } else if (fields->size() != header.size()) {
    record.problem = where + std::to_string(fields->size()) + " fields where the header has " +
                     std::to_string(header.size());
  } else {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (!header[i].empty()) add_field(record, header[i], (*fields)[i], number);
    }
  }
  return record;
}

/// The header's column names, trimmed; an error if one is given twice (which column would count?).
Result<std::vector<std::string>> read_header(std::string_view line, int number) {
  const std::optional<std::vector<std::string>> fields = split_csv(line);
  if (!fields) return fail("line " + std::to_string(number) + ": header: a quote not closed");
  std::vector<std::string> names;
  std::set<std::string, std::less<>> seen;
  for (const std::string& field : *fields) {
    names.emplace_back(trim(field));
    if (!names.back().empty() && !seen.insert(names.back()).second) {
      return fail("line " + std::to_string(number) + ": header: column " + names.back() +
                  " given twice");
    }
  }
  return names;
}

}  // namespace

OmmRecords read_omm_csv(std::string_view text) {
  OmmRecords out;
  const std::vector<std::string_view> lines = split_lines(text);
  std::optional<std::vector<std::string>> header;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int number = static_cast<int>(i + 1);
    if (trim(lines[i]).empty()) continue;
    if (header) {
      out.records.push_back(read_row(lines[i], number, *header));
      continue;
    }
    Result<std::vector<std::string>> names = read_header(lines[i], number);
    if (!names) {
      out.errors.push_back(names.error().message);
      return out;
    }
    header = std::move(names).value();
  }
  return out;
}

}  // namespace azt::orbit
