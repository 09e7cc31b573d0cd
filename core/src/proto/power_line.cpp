#include "azt/proto/power_line.hpp"

#include <cmath>
#include <string>

#include "azt/util/parse_number.hpp"
#include "azt/util/quote.hpp"
#include "azt/util/text_lines.hpp"

namespace azt::proto {
namespace {

constexpr std::string_view kBlanks = " \t";
/// A line quoted in an error message is cut to this.
constexpr std::size_t kShownChars = 24;
static_assert(kPowerLineMaxAbsDb == 300.0, "the range error message says ±300 dB");

char to_lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

/// A line for an error message: quoted, cut short, bytes that are not printable ASCII as '?'.
std::string shown(std::string_view line) {
  std::string printable(line.substr(0, kShownChars + 1));
  for (char& c : printable) {
    if (c < ' ' || c > '~') c = '?';
  }
  return quote(printable, kShownChars);
}

/// `text` without a final "dB" (any case) and the blanks before it.
std::string_view without_unit(std::string_view text) {
  if (text.size() >= 2 && to_lower(text[text.size() - 2]) == 'd' && to_lower(text.back()) == 'b') {
    text.remove_suffix(2);
    return trim(text, kBlanks);
  }
  return text;
}

}  // namespace

Result<double> parse_power_line(std::string_view line) {
  if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() > kPowerLineMaxChars) {
    return fail("power: line longer than " + std::to_string(kPowerLineMaxChars) + " characters");
  }
  const std::string_view text = trim(line, kBlanks);
  if (text.empty()) return fail("power: empty line");
  const std::string_view number = without_unit(text);
  if (number.empty()) return fail("power: no number before dB");
  const auto db = parse_finite_double(number);
  if (!db) return fail("power: not a finite number in dB: " + shown(text));
  if (std::fabs(*db) > kPowerLineMaxAbsDb) {
    return fail("power: " + shown(text) + " is beyond ±300 dB");
  }
  return *db;
}

std::vector<Result<double>> parse_power_lines(std::string_view text) {
  std::vector<Result<double>> readings;
  for (const std::string_view line : split_lines(text)) {
    if (trim(line, kBlanks).empty()) continue;
    readings.push_back(parse_power_line(line));
  }
  return readings;
}

}  // namespace azt::proto
