#pragma once
// The scan log as CSV (docs/calibration.md), to export, to import results from other tools or
// earlier sessions, and as the daemon's log file (one row appended per line of a scan).
//
// The first line that is not blank or a comment (#) names the columns, in any order, case-blind:
// utc, az_deg (or az), el_deg (el), daz_deg (daz), del_deg (del) are needed; source, weight,
// measured (both | az | el), sigma_xel_deg, sigma_el_deg, snr_db, rise_db, beamwidth_deg may
// follow; other columns are skipped. Then one row per line: fields split at commas, blanks around
// them ignored, an optional field may be empty. Quoted fields are not read (no value needs one).
// Any other bad byte, a missing or unparsable field, a value out of range, a row with the wrong
// number of fields, or a line over kScanLogMaxLineChars is refused with its line number and the
// column; nothing of a refused file is taken.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "azt/calibration/scan_log.hpp"
#include "azt/util/result.hpp"

namespace azt::calibration {

constexpr std::size_t kScanLogMaxLineChars = 1024;
constexpr std::size_t kScanLogMaxRows = 100000;
constexpr std::size_t kScanLogMaxSourceChars = 40;

/// The header this codec writes (no newline).
std::string scan_log_csv_header();
/// One row (no newline): angles to 1e-6°, dB to 0.01, the UTC to the millisecond, standard
/// errors and beamwidths exactly (their ranges are open at 0).
std::string scan_log_csv_row(const ScanLogEntry& entry);
/// Header and rows, each line ending in a newline.
std::string write_scan_log_csv(const std::vector<ScanLogEntry>& log);

/// Reads a scan log (the rules above). Errors read "line N: column: what is wrong".
Result<std::vector<ScanLogEntry>> read_scan_log_csv(std::string_view text);

}  // namespace azt::calibration
