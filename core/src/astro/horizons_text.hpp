#pragma once
// What the two Horizons readers share (horizons_vectors.cpp, horizons_observer.cpp): the header
// lines, the $$SOE/$$EOE body, the column block, numbers and times, and errors that name a line.
//
// Layout of Horizons text output: astroquery's test data (jplhorizons/tests/data/ceres_vectors.txt,
// ceres_ephemerides.txt) and API v1.2 replies; https://ssd-api.jpl.nasa.gov/doc/horizons.html.
// The header is "Key : value" lines; the column names sit between the last two star lines before
// $$SOE; the records run from $$SOE to $$EOE.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/astro/time_scales.hpp"
#include "azt/util/result.hpp"

namespace azt::astro::horizons_text {

inline constexpr double kAuKm = 149597870.7;  // IAU 2012 B2, as the Horizons header states.

using Lines = std::vector<std::string_view>;

/// The comma-separated fields of a line, each trimmed.
std::vector<std::string_view> split_commas(std::string_view line);

/// A line of asterisks only: the rules around the column names.
bool is_star_line(std::string_view line);

/// "Horizons vector table, line 28 (Reference frame : Ecliptic of J2000.0): why".
Error line_error(std::string_view table, std::size_t index, std::string_view line,
                 std::string_view why);

struct HeaderField {
  std::size_t index;
  std::string_view line;
  std::string_view value;
};

/// The header line `key<spaces>: value` before `end`, if any.
std::optional<HeaderField> header_field(const Lines& lines, std::size_t end, std::string_view key);

/// "Moon (301)                      {source: DE441}" -> "Moon (301)".
std::string without_source_note(std::string_view value);

struct Body {
  std::size_t soe;  ///< Index of the $$SOE line.
  std::size_t eoe;  ///< Index of the $$EOE line.
};

/// The $$SOE and $$EOE lines, or an error naming `table` and what is missing.
Result<Body> find_body(const Lines& lines, std::string_view table);

/// Indices of the column-name lines: between the last two star lines before $$SOE.
std::vector<std::size_t> column_block(const Lines& lines, std::size_t soe);

/// A finite number, blanks around it ignored.
std::optional<double> parse_field(std::string_view text);

/// A Julian date as written by Horizons ("2460735.506944444"), split at the point so the
/// fraction keeps its ~1e-9 day (86 µs) digits exactly.
std::optional<JulianDate> parse_jd(std::string_view text);

/// `to` − `from` in days, the whole and fractional parts apart (see parse_jd).
double days_between(const JulianDate& from, const JulianDate& to);

/// Strictly increasing node times, counted from the first, or an error naming the record.
Result<std::vector<double>> offsets_from_first(const std::vector<JulianDate>& times,
                                               const std::vector<std::size_t>& line_index,
                                               const Lines& lines, std::string_view table);

/// Index i with offsets[i] <= t <= offsets[i + 1], or nullopt outside [front, back].
std::optional<std::size_t> bracket(const std::vector<double>& offsets, double t);

/// "TABLE for TARGET covers SCALE JD first .. last; asked for JD asked".
Error out_of_span(std::string_view table, const std::string& target, std::string_view scale,
                  const JulianDate& first, double last_offset_days, const JulianDate& asked);

}  // namespace azt::astro::horizons_text
