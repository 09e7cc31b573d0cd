#pragma once
// The daemon's scan log file, `scan-log.csv` beside the configuration (docs/calibration.md "In
// the daemon"): the core's CSV (scan_log_csv.hpp), a header and then rows appended a scan at a
// time. Read at start row by row, so that one bad row (a hand edit, a torn disk block) costs that
// row alone, said in the journal, and the rest are kept.

#include <string>
#include <string_view>
#include <vector>

#include "azt/calibration/scan_log.hpp"

namespace azt::app {

struct LoadedScanLog {
  std::vector<calibration::ScanLogEntry> rows;
  std::vector<std::string> refused;  ///< "line N: column: what is wrong", one per bad row
};

/// Reads the file's text: the header, then each row on its own.
LoadedScanLog read_scan_log_file(std::string_view text);

/// The lines to append for `rows`, the header first when the file is new (or empty).
std::string scan_log_lines(const std::vector<calibration::ScanLogEntry>& rows, bool with_header);

}  // namespace azt::app
