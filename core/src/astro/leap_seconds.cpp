#include "azt/astro/leap_seconds.hpp"
#include "azt/util/quote.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <iterator>
#include <string>
#include <system_error>

namespace azt::astro {

namespace {

/// NTP timestamps count seconds since 1900-01-01T00:00:00Z; MJD = ntp / 86400 + 15020
/// (the conversion stated in leap-seconds.list itself).
constexpr std::int64_t kSecondsPerDay = 86400;
constexpr std::int64_t kNtpEpochMjd = 15020;
/// 1972-01-01, the first day of the present UTC system (TAI − UTC = 10 s).
constexpr std::int64_t kFirstUtcStepMjd = 41317;
constexpr std::size_t kMaxQuotedChars = 80;  ///< of a bad line, in an error message

struct NtpStep {
  std::int64_t ntp_s;
  int tai_minus_utc_s;
};

/// IERS Bulletin C history, copied from /usr/share/zoneinfo/leap-seconds.list (Debian tzdata 2025b;
/// last step 2017-01-01, 37 s). NTP seconds are kept as printed there so the lines can be diffed.
constexpr NtpStep kBuiltinSteps[] = {
    {2272060800, 10},  // 1 Jan 1972
    {2287785600, 11},  // 1 Jul 1972
    {2303683200, 12},  // 1 Jan 1973
    {2335219200, 13},  // 1 Jan 1974
    {2366755200, 14},  // 1 Jan 1975
    {2398291200, 15},  // 1 Jan 1976
    {2429913600, 16},  // 1 Jan 1977
    {2461449600, 17},  // 1 Jan 1978
    {2492985600, 18},  // 1 Jan 1979
    {2524521600, 19},  // 1 Jan 1980
    {2571782400, 20},  // 1 Jul 1981
    {2603318400, 21},  // 1 Jul 1982
    {2634854400, 22},  // 1 Jul 1983
    {2698012800, 23},  // 1 Jul 1985
    {2776982400, 24},  // 1 Jan 1988
    {2840140800, 25},  // 1 Jan 1990
    {2871676800, 26},  // 1 Jan 1991
    {2918937600, 27},  // 1 Jul 1992
    {2950473600, 28},  // 1 Jul 1993
    {2982009600, 29},  // 1 Jul 1994
    {3029443200, 30},  // 1 Jan 1996
    {3076704000, 31},  // 1 Jul 1997
    {3124137600, 32},  // 1 Jan 1999
    {3345062400, 33},  // 1 Jan 2006
    {3439756800, 34},  // 1 Jan 2009
    {3550089600, 35},  // 1 Jul 2012
    {3644697600, 36},  // 1 Jul 2015
    {3692217600, 37},  // 1 Jan 2017
};
/// The list's `#@` expiry line: 28 June 2026 (MJD 61219).
constexpr std::int64_t kBuiltinExpiryNtpS = 3991593600;

/// Precondition: `ntp_s` is a multiple of 86400 (00:00 UTC), so the division is exact.
double ntp_day_to_mjd(std::int64_t ntp_s) {
  const std::int64_t mjd = ntp_s / kSecondsPerDay + kNtpEpochMjd;
  return static_cast<double>(mjd);
}

std::string line_error(std::size_t line_no, std::string_view what) {
  return "leap-seconds list line " + std::to_string(line_no) + ": " + std::string(what);
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Splits `text` at blanks into at most `max_tokens` + 1 tokens (the extra one signals junk).
std::vector<std::string_view> split_blanks(std::string_view text, std::size_t max_tokens) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < text.size() && tokens.size() <= max_tokens) {
    while (i < text.size() && is_blank(text[i])) ++i;
    const std::size_t start = i;
    while (i < text.size() && !is_blank(text[i])) ++i;
    if (i > start) tokens.push_back(text.substr(start, i - start));
  }
  return tokens;
}

template <typename Int>
bool parse_whole(std::string_view token, Int& out) {
  const char* end = token.data() + token.size();
  auto [ptr, ec] = std::from_chars(token.data(), end, out);
  return ec == std::errc{} && ptr == end;
}

/// An NTP timestamp that must fall on 00:00 UTC of a day on or after 1972-01-01.
Result<double> parse_ntp_day(std::string_view token, std::size_t line_no, std::string_view what) {
  std::int64_t ntp_s = 0;
  if (!parse_whole(token, ntp_s) || ntp_s < 0) {
    return fail(line_error(line_no, std::string(what) + " \"" + std::string(token) +
                                        "\" is not a whole number of NTP seconds"));
  }
  if (ntp_s % kSecondsPerDay != 0) {
    return fail(line_error(line_no, std::string(what) + " " + std::string(token) +
                                        " is not at 00:00 UTC (not a multiple of 86400 s)"));
  }
  const double mjd = ntp_day_to_mjd(ntp_s);
  if (mjd < static_cast<double>(kFirstUtcStepMjd)) {
    return fail(line_error(line_no, std::string(what) + " " + std::string(token) +
                                        " is before 1972-01-01, the start of leap-second UTC"));
  }
  return mjd;
}

/// A data line `NTP_SECONDS TAI-UTC [# comment]`, appended to `steps` after the order checks.
std::optional<Error> add_data_line(std::string_view line, std::size_t line_no,
                                   std::vector<LeapSecondTable::Step>& steps) {
  const auto tokens = split_blanks(line.substr(0, line.find('#')), 2);
  if (tokens.size() != 2) {
    return fail(line_error(
        line_no, "expected \"NTP_SECONDS TAI-UTC\", got " + quote(line, kMaxQuotedChars)));
  }
  auto mjd = parse_ntp_day(tokens[0], line_no, "timestamp");
  if (!mjd) return mjd.error();
  int offset_s = 0;
  if (!parse_whole(tokens[1], offset_s)) {
    return fail(line_error(
        line_no, "TAI-UTC \"" + std::string(tokens[1]) + "\" is not a whole number of seconds"));
  }
  if (!steps.empty()) {
    const auto& prev = steps.back();
    if (*mjd <= prev.mjd_utc) {
      return fail(line_error(line_no, "step out of order (not after the previous line's date)"));
    }
    // 64-bit: two extreme ints must not overflow while we complain about them.
    const std::int64_t change_s =
        std::int64_t{offset_s} - static_cast<std::int64_t>(prev.tai_minus_utc_s);
    if (change_s != 1 && change_s != -1) {
      return fail(line_error(line_no, "TAI-UTC changes by " + std::to_string(change_s) +
                                          " s; a leap second changes it by exactly 1 s"));
    }
  }
  steps.push_back({*mjd, static_cast<double>(offset_s)});
  return std::nullopt;
}

}  // namespace

const LeapSecondTable& LeapSecondTable::builtin() {
  static const LeapSecondTable table = [] {
    std::vector<Step> steps;
    steps.reserve(std::size(kBuiltinSteps));
    for (const auto& s : kBuiltinSteps) {
      steps.push_back({ntp_day_to_mjd(s.ntp_s), static_cast<double>(s.tai_minus_utc_s)});
    }
    return LeapSecondTable(std::move(steps), ntp_day_to_mjd(kBuiltinExpiryNtpS));
  }();
  return table;
}

Result<LeapSecondTable> LeapSecondTable::parse_ietf_list(std::string_view text) {
  std::vector<Step> steps;
  std::optional<double> expiry_mjd;
  std::size_t expiry_line = 0;
  std::size_t line_no = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    ++line_no;
    while (!line.empty() && is_blank(line.front())) line.remove_prefix(1);
    while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
    if (line.empty()) continue;
    if (line.substr(0, 2) == "#@") {
      if (expiry_mjd) {
        return fail(line_error(
            line_no, "second expiry line (first on line " + std::to_string(expiry_line) + ")"));
      }
      const auto tokens = split_blanks(line.substr(2), 1);
      if (tokens.size() != 1) return fail(line_error(line_no, "expected \"#@ NTP_SECONDS\""));
      auto mjd = parse_ntp_day(tokens[0], line_no, "expiry");
      if (!mjd) return mjd.error();
      expiry_mjd = *mjd;
      expiry_line = line_no;
    } else if (line.front() != '#') {
      if (auto err = add_data_line(line, line_no, steps)) return *err;
    }
  }
  if (steps.empty()) return fail("leap-seconds list has no data lines");
  if (!expiry_mjd) return fail("leap-seconds list has no expiry line (\"#@ NTP_SECONDS\")");
  if (*expiry_mjd <= steps.back().mjd_utc) {
    return fail(line_error(expiry_line, "expiry is not after the last leap second"));
  }
  return LeapSecondTable(std::move(steps), *expiry_mjd);
}

std::optional<double> LeapSecondTable::tai_minus_utc(double mjd_utc) const {
  // `!(a >= b)` also catches NaN, which upper_bound would otherwise place after every step.
  if (steps_.empty() || !(mjd_utc >= steps_.front().mjd_utc)) return std::nullopt;
  // Steps ascend (the parser checks it; builtin() is sorted): find the last one at or before.
  const auto after =
      std::upper_bound(steps_.begin(), steps_.end(), mjd_utc,
                       [](double mjd, const Step& step) { return mjd < step.mjd_utc; });
  return std::prev(after)->tai_minus_utc_s;
}

}  // namespace azt::astro
