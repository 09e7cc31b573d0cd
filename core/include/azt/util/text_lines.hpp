#pragma once
// Line-oriented text as the file readers see it (TLE catalogues, Horizons tables, OMM files).

#include <string_view>
#include <vector>

namespace azt {

/// The lines of `text`, split at LF, each without a trailing CR; a final newline gives no extra
/// empty line. The views point into `text`.
std::vector<std::string_view> split_lines(std::string_view text);

/// `text` without leading and trailing characters of `blanks`.
std::string_view trim(std::string_view text, std::string_view blanks = " \t");

}  // namespace azt
