// OMM in CCSDS KVN (502.0-B-3): "KEYWORD = value" lines, an optional "[units]" after the value,
// COMMENT lines and blank lines ignored. Each message starts with CCSDS_OMM_VERS, so a file of
// several concatenated messages (one per object) splits there.

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/orbit/omm_record.hpp"

namespace azt::orbit {

namespace {

constexpr std::string_view kVersionKey = "CCSDS_OMM_VERS";

bool is_keyword(std::string_view key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

bool is_comment(std::string_view line) {
  constexpr std::string_view kComment = "COMMENT";
  return line.substr(0, kComment.size()) == kComment &&
         (line.size() == kComment.size() || line[kComment.size()] == ' ' ||
          line[kComment.size()] == '\t');
}

/// META_START, DATA_STOP and the like: block markers some writers add; they carry no value.
bool is_block_marker(std::string_view line) {
  const auto ends_with = [&](std::string_view tail) {
    return line.size() > tail.size() && line.substr(line.size() - tail.size()) == tail;
  };
  return is_keyword(line) && (ends_with("_START") || ends_with("_STOP"));
}

/// "15.5 [rev/day]" → "15.5": the units are the standard's, fixed per keyword.
std::string_view strip_units(std::string_view value) {
  if (!value.empty() && value.back() == ']') {
    const std::size_t open = value.rfind('[');
    if (open != std::string_view::npos) return trim(value.substr(0, open));
  }
  return value;
}

std::string line_problem(int number, std::string_view what) {
  return "line " + std::to_string(number) + ": " + std::string(what);
}

/// Walks the lines, starting a record at each CCSDS_OMM_VERS.
class KvnReader {
 public:
  void feed(std::string_view raw, int number) {
    const std::string_view line = trim(raw);
    if (line.empty() || is_comment(line) || is_block_marker(line)) return;
    const std::size_t equals = line.find('=');
    const std::string_view key = trim(line.substr(0, equals));
    if (equals == std::string_view::npos || !is_keyword(key)) {
      constexpr std::size_t kShown = 40;
      report(line_problem(number,
                          "'" + std::string(line.substr(0, kShown)) + "' is not KEYWORD = value"));
      return;
    }
    if (key == kVersionKey) {
      OmmRecord record;
      record.line = number;
      record.theory_required = true;
      out_.records.push_back(std::move(record));
    }
    if (out_.records.empty()) {
      report(
          line_problem(number, std::string(key) + " before the first " + std::string(kVersionKey)));
      return;
    }
    add_field(out_.records.back(), key, strip_units(trim(line.substr(equals + 1))), number);
  }

  OmmRecords finish() { return std::move(out_); }

 private:
  /// A problem belongs to the object it is in; before the first object, to the file (once:
  /// a prelude of many lines is one mistake).
  void report(std::string problem) {
    if (!out_.records.empty()) {
      OmmRecord& record = out_.records.back();
      if (record.problem.empty()) record.problem = std::move(problem);
    } else if (!prelude_reported_) {
      out_.errors.push_back(std::move(problem));
      prelude_reported_ = true;
    }
  }

  OmmRecords out_;
  bool prelude_reported_ = false;
};

}  // namespace

OmmRecords read_omm_kvn(std::string_view text) {
  KvnReader reader;
  const std::vector<std::string_view> lines = split_lines(text);
  for (std::size_t i = 0; i < lines.size(); ++i) reader.feed(lines[i], static_cast<int>(i + 1));
  return reader.finish();
}

}  // namespace azt::orbit
