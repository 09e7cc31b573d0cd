#include "calibration/scan_log_file.hpp"

#include "azt/calibration/scan_log_csv.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::app {
namespace {

bool skipped(std::string_view line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string_view::npos || line[first] == '#';
}

/// The reader's "line 2: …" of a header and one row, as the file's line `number`.
std::string at_line(const std::string& message, std::size_t number) {
  const auto colon = message.find(": ");
  const std::string what = message.rfind("line ", 0) == 0 && colon != std::string::npos
                               ? message.substr(colon + 2)
                               : message;
  return "line " + std::to_string(number) + ": " + what;
}

}  // namespace

LoadedScanLog read_scan_log_file(std::string_view text) {
  LoadedScanLog out;
  std::string header;
  std::size_t number = 0;
  for (const std::string_view line : split_lines(text)) {
    ++number;
    if (skipped(line)) continue;
    if (header.empty()) {
      header = std::string(line);
      continue;
    }
    auto rows = calibration::read_scan_log_csv(header + "\n" + std::string(line) + "\n");
    if (!rows) {
      out.refused.push_back(at_line(rows.error().message, number));
      continue;
    }
    out.rows.insert(out.rows.end(), rows->begin(), rows->end());
  }
  return out;
}

std::string scan_log_lines(const std::vector<calibration::ScanLogEntry>& rows, bool with_header) {
  std::string text = with_header ? calibration::scan_log_csv_header() + "\n" : std::string();
  for (const calibration::ScanLogEntry& row : rows) {
    text += calibration::scan_log_csv_row(row);
    text += '\n';
  }
  return text;
}

}  // namespace azt::app
