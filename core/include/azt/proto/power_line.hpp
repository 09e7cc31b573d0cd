#pragma once
// The simplest receiver power feed (docs/calibration.md): one power reading in dB per line, so any
// SDR program, script or `echo` can send it, as UDP datagrams or lines on a pipe or file:
//
//   -42.1
//   -41.87 dB
//   +3.5dB\r\n
//
// A line is a decimal number (from_chars' general form: "-42.1", "4.2e1"; one leading '+'
// allowed), optionally followed by "dB" in any letter case, with or without spaces before it.
// Spaces and tabs around the whole line and a trailing "\r" (or "\r\n") are tolerated. Anything
// else is refused with the reason: NaN and infinities, values beyond ±kPowerLineMaxAbsDb, other
// units ("dBm" is refused too, rather than guessing what the sender meant), junk, an empty line,
// and lines longer than kPowerLineMaxChars.

#include <cstddef>
#include <string_view>
#include <vector>

#include "azt/util/result.hpp"

namespace azt::proto {

/// Readings beyond ±this are not a receiver's power on any scale (and keep 10^(dB/10) finite).
inline constexpr double kPowerLineMaxAbsDb = 300.0;
/// A reading is a few characters; a longer line is junk and is not parsed.
inline constexpr std::size_t kPowerLineMaxChars = 64;

/// Parses one line (with or without its terminator). Pure, locale-free.
Result<double> parse_power_line(std::string_view line);

/// Parses every line of a datagram or chunk of text, split at LF (util/text_lines.hpp's
/// split_lines, so each line loses its trailing CR). Lines holding only spaces and tabs carry no
/// reading and give no result, so "-42.1\n\n" is one reading, and an empty datagram none.
/// One result per other line, in order: the caller counts each error as a malformed reading.
std::vector<Result<double>> parse_power_lines(std::string_view text);

}  // namespace azt::proto
