#include "azt/calibration/scan_log_csv.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "azt/util/format_number.hpp"
#include "azt/util/parse_number.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::calibration {
namespace {

enum class Column {
  Utc,
  Source,
  Az,
  El,
  Daz,
  Del,
  Weight,
  Measured,
  SigmaXel,
  SigmaEl,
  Snr,
  Rise,
  Beamwidth,
  Skipped,
};

struct ColumnSpec {
  Column column;
  std::string_view name;
  std::string_view alias;
  bool needed;
};

/// In the order the export writes them.
constexpr std::array<ColumnSpec, 13> kColumns{{
    {Column::Utc, "utc", "utc", true},
    {Column::Source, "source", "source", false},
    {Column::Az, "az_deg", "az", true},
    {Column::El, "el_deg", "el", true},
    {Column::Daz, "daz_deg", "daz", true},
    {Column::Del, "del_deg", "del", true},
    {Column::Weight, "weight", "weight", false},
    {Column::Measured, "measured", "measured", false},
    {Column::SigmaXel, "sigma_xel_deg", "sigma_xel", false},
    {Column::SigmaEl, "sigma_el_deg", "sigma_el", false},
    {Column::Snr, "snr_db", "snr", false},
    {Column::Rise, "rise_db", "rise", false},
    {Column::Beamwidth, "beamwidth_deg", "beamwidth", false},
}};

/// A number's range; `above_min`: the minimum itself is refused.
struct Range {
  double min;
  double max;
  bool above_min;
};

Range range_of(Column c) {
  switch (c) {
    case Column::Az:
      return {0.0, 360.0, false};
    case Column::El:
      return {0.0, 90.0, false};
    case Column::Daz:
      return {-180.0, 180.0, false};
    case Column::Del:
      return {-90.0, 90.0, false};
    case Column::Weight:
      return {0.0, 1e6, false};
    case Column::SigmaXel:
    case Column::SigmaEl:
      return {0.0, 10.0, true};
    case Column::Snr:
    case Column::Rise:
      return {-100.0, 300.0, false};
    case Column::Beamwidth:
      return {0.0, 30.0, true};
    case Column::Utc:
    case Column::Source:
    case Column::Measured:
    case Column::Skipped:
      break;
  }
  return {0.0, 0.0, false};
}

std::string_view name_of(Column c) {
  for (const ColumnSpec& s : kColumns) {
    if (s.column == c) return s.name;
  }
  return "?";
}

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(), [](char ch) {
    return ch >= 'A' && ch <= 'Z' ? static_cast<char>(ch - 'A' + 'a') : ch;
  });
  return out;
}

/// The field, for a message, when it is short and printable ASCII; else nothing.
std::string shown(std::string_view field) {
  constexpr std::size_t kShownChars = 24;
  const bool printable =
      std::all_of(field.begin(), field.end(), [](char ch) { return ch >= 0x20 && ch < 0x7f; });
  if (!printable || field.size() > kShownChars) return "";
  return " (\"" + std::string(field) + "\")";
}

Error at(std::size_t line, std::string_view column, const std::string& what) {
  return fail("line " + std::to_string(line) + ": " + std::string(column) + ": " + what);
}

Error at(std::size_t line, const std::string& what) {
  return fail("line " + std::to_string(line) + ": " + what);
}

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  while (true) {
    const std::size_t comma = line.find(',');
    out.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return out;
    line.remove_prefix(comma + 1);
  }
}

/// Refuses what no field may hold.
std::optional<std::string> bad_bytes(std::string_view line) {
  if (line.size() > kScanLogMaxLineChars) {
    return "longer than " + std::to_string(kScanLogMaxLineChars) + " characters";
  }
  for (const char ch : line) {
    const auto b = static_cast<unsigned char>(ch);
    if (ch == '"') return "quoted fields are not read";
    if ((b < 0x20 && ch != '\t') || b == 0x7f) return "a control character";
  }
  return std::nullopt;
}

bool source_char(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
         std::string_view(" _.+*()/-").find(ch) != std::string_view::npos;
}

Result<std::vector<Column>> read_header(std::string_view line, std::size_t n) {
  if (auto bad = bad_bytes(line)) return at(n, "header: " + *bad);
  std::vector<Column> out;
  for (const std::string_view field : fields_of(line)) {
    const std::string name = lower(field);
    Column c = Column::Skipped;
    for (const ColumnSpec& s : kColumns) {
      if (name == s.name || name == s.alias) c = s.column;
    }
    if (c != Column::Skipped && std::find(out.begin(), out.end(), c) != out.end()) {
      return at(n, "header: " + std::string(name_of(c)) + " appears twice");
    }
    out.push_back(c);
  }
  for (const ColumnSpec& s : kColumns) {
    if (s.needed && std::find(out.begin(), out.end(), s.column) == out.end()) {
      return at(n, "header: no " + std::string(s.name) + " column");
    }
  }
  return out;
}

Result<double> number(Column c, std::string_view field, std::size_t n) {
  const auto value = parse_finite_double(field);
  if (!value) return at(n, name_of(c), "not a number" + shown(field));
  const Range r = range_of(c);
  const bool low = r.above_min ? !(*value > r.min) : !(*value >= r.min);
  if (low || *value > r.max) {
    return at(n, name_of(c),
              format_number(*value) + " is outside " + (r.above_min ? "(" : "[") +
                  format_number(r.min) + ", " + format_number(r.max) + "]");
  }
  return *value;
}

Result<bool> set_text(ScanLogEntry& e, Column c, std::string_view field, std::size_t n) {
  if (c == Column::Utc) {
    const auto utc = astro::parse_iso8601_utc(field);
    if (!utc) return at(n, "utc", "not an ISO 8601 UTC time such as 2025-06-01T16:00:00Z");
    e.utc = *utc;
    return true;
  }
  if (c == Column::Measured) {
    const auto m = parse_measured(field);
    if (!m) return at(n, "measured", "must be both, az or el" + shown(field));
    e.measured = *m;
    return true;
  }
  if (field.size() > kScanLogMaxSourceChars ||
      !std::all_of(field.begin(), field.end(), source_char)) {
    return at(n, "source",
              "at most " + std::to_string(kScanLogMaxSourceChars) +
                  " letters, digits, spaces and _.+*()/-");
  }
  e.source = std::string(field);
  return true;
}

Result<bool> set_number(ScanLogEntry& e, Column c, std::string_view field, std::size_t n) {
  const auto value = number(c, field, n);
  if (!value) return value.error();
  switch (c) {
    case Column::Az:
      e.az_deg = *value;
      break;
    case Column::El:
      e.el_deg = *value;
      break;
    case Column::Daz:
      e.daz_deg = *value;
      break;
    case Column::Del:
      e.del_deg = *value;
      break;
    case Column::Weight:
      e.weight = *value;
      break;
    case Column::SigmaXel:
      e.sigma_xel_deg = *value;
      break;
    case Column::SigmaEl:
      e.sigma_el_deg = *value;
      break;
    case Column::Snr:
      e.snr_db = *value;
      break;
    case Column::Rise:
      e.rise_db = *value;
      break;
    case Column::Beamwidth:
      e.beamwidth_deg = *value;
      break;
    case Column::Utc:
    case Column::Source:
    case Column::Measured:
    case Column::Skipped:
      break;
  }
  return true;
}

Result<bool> set_field(ScanLogEntry& e, Column c, std::string_view field, std::size_t n) {
  if (c == Column::Skipped) return true;
  if (field.empty()) {
    const bool needed = std::any_of(kColumns.begin(), kColumns.end(),
                                    [c](const ColumnSpec& s) { return s.column == c && s.needed; });
    if (needed) return at(n, name_of(c), "empty");
    return true;
  }
  const bool text = c == Column::Utc || c == Column::Source || c == Column::Measured;
  return text ? set_text(e, c, field, n) : set_number(e, c, field, n);
}

Result<ScanLogEntry> read_row(std::string_view line, std::size_t n,
                              const std::vector<Column>& columns) {
  if (auto bad = bad_bytes(line)) return at(n, *bad);
  const std::vector<std::string_view> fields = fields_of(line);
  if (fields.size() != columns.size()) {
    return at(n, std::to_string(fields.size()) + " fields, the header has " +
                     std::to_string(columns.size()));
  }
  ScanLogEntry e;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (auto ok = set_field(e, columns[i], fields[i], n); !ok) return ok.error();
  }
  return e;
}

std::string optional_fixed(const std::optional<double>& v, int decimals) {
  return v ? format_fixed(*v, decimals) : std::string();
}

/// For the values whose range is open at 0: the shortest text that reads back exactly.
std::string optional_shortest(const std::optional<double>& v) {
  return v ? format_number(*v) : std::string();
}

}  // namespace

std::string scan_log_csv_header() {
  std::string out;
  for (const ColumnSpec& s : kColumns) out += std::string(out.empty() ? "" : ",") += s.name;
  return out;
}

std::string scan_log_csv_row(const ScanLogEntry& e) {
  return astro::format_iso8601_utc(e.utc) + "," + e.source + "," + format_fixed(e.az_deg, 6) + "," +
         format_fixed(e.el_deg, 6) + "," + format_fixed(e.daz_deg, 6) + "," +
         format_fixed(e.del_deg, 6) + "," + format_number(e.weight) + "," +
         std::string(to_string(e.measured)) + "," + optional_shortest(e.sigma_xel_deg) + "," +
         optional_shortest(e.sigma_el_deg) + "," + optional_fixed(e.snr_db, 2) + "," +
         optional_fixed(e.rise_db, 2) + "," + optional_shortest(e.beamwidth_deg);
}

std::string write_scan_log_csv(const std::vector<ScanLogEntry>& log) {
  std::string out = scan_log_csv_header() + "\n";
  for (const ScanLogEntry& e : log) out += scan_log_csv_row(e) + "\n";
  return out;
}

Result<std::vector<ScanLogEntry>> read_scan_log_csv(std::string_view text) {
  std::optional<std::vector<Column>> columns;
  std::vector<ScanLogEntry> out;
  std::size_t n = 0;
  for (const std::string_view raw : split_lines(text)) {
    ++n;
    const std::string_view line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    if (!columns) {
      auto header = read_header(line, n);
      if (!header) return header.error();
      columns = std::move(header).value();
      continue;
    }
    if (out.size() >= kScanLogMaxRows) {
      return at(n, "more than " + std::to_string(kScanLogMaxRows) + " rows");
    }
    auto row = read_row(line, n, *columns);
    if (!row) return row.error();
    out.push_back(std::move(row).value());
  }
  if (!columns) return fail("no header line: the first line must name the columns");
  return out;
}

}  // namespace azt::calibration
