#pragma once
// Two- and three-line element sets (TLE) as NORAD and CelesTrak publish them (docs/satellites.md).
//
// Column layout: CelesTrak, "NORAD Two-Line Element Set Format"
// (https://celestrak.org/NORAD/documentation/tle-fmt.php); the epoch conversion follows Vallado's
// days2mdhms and jday (Vallado et al. 2006, "Revisiting Spacetrack Report #3", AIAA 2006-6753) so
// that SGP4 starts from the very Julian date the reference code uses.

#include <string>
#include <string_view>
#include <vector>

#include "azt/orbit/elements.hpp"
#include "azt/util/result.hpp"

namespace azt::orbit {

struct TleOptions {
  /// Check the mod-10 checksum in column 69 of each line. Only the hand-made cases of the
  /// SGP4 verification set (33333–33335) need this off: their lines were edited without it.
  bool verify_checksum = true;
};

/// One element set from its lines: `line1` and `line2` exactly as in the file (69 characters; a
/// trailing '\r' or blanks are ignored) and `name`, line 0 of a three-line set, possibly empty or
/// with its "0 " prefix. Errors read "<name or number>: line 2, column 27: eccentricity: …" with
/// the lines numbered 1 and 2 (0 for the name).
Result<Elements> parse_tle(std::string_view line1, std::string_view line2,
                           std::string_view name = {}, const TleOptions& options = {});

/// What a catalogue file gave: the good element sets in file order, and one message per bad
/// entry. A malformed entry is an error for that entry alone.
struct TleParse {
  std::vector<Elements> sets;
  std::vector<std::string> errors;
};

/// A whole catalogue as CelesTrak serves it: any mix of two- and three-line entries, LF or CRLF,
/// blank lines ignored. Messages name the entry and the line and column in the file
/// ("ISS (ZARYA): line 5, column 19: epoch: not a number").
TleParse parse_tle_catalogue(std::string_view text, const TleOptions& options = {});

/// The TLE checksum of a line: digits count their value, '-' counts 1, the rest 0, over
/// columns 1–68, modulo 10.
int tle_checksum(std::string_view line);

/// The catalogue number of a TLE catalogue field: "25544" → 25544, alpha-5 "A0001" → 100001
/// (letters A–Z without I and O stand for 10–33). Error for anything else.
Result<long> catalog_number(std::string_view field);

/// UTC Julian date of a TLE epoch, split as whole + fraction the way Vallado's jday returns it.
struct JulianDate {
  double whole = 0.0;
  double fraction = 0.0;
};
/// `two_digit_year` 57–99 means 19xx, 00–56 means 20xx; `day_of_year` is 1.0 at 0 h on 1 January.
JulianDate tle_epoch_to_jd(int two_digit_year, double day_of_year);

}  // namespace azt::orbit
