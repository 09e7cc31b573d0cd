// ISO 8601 / RFC 3339 text for UTC instants: a strict parser and a millisecond formatter.

#include <erfa.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <system_error>

#include "azt/astro/time_scales.hpp"
#include "azt/util/quote.hpp"

namespace azt::astro {

namespace {

constexpr std::int64_t kMsPerDay = 86'400'000;

Error bad(std::string_view text, const std::string& why) {
  return fail(quote(text) + " is not a UTC time YYYY-MM-DDTHH:MM[:SS[.fff]]Z: " + why);
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// Reads exactly `count` digits at `pos`.
std::optional<int> digits_at(std::string_view text, std::size_t pos, std::size_t count) {
  if (pos + count > text.size()) return std::nullopt;
  int value = 0;
  for (std::size_t i = pos; i < pos + count; ++i) {
    if (!is_digit(text[i])) return std::nullopt;
    value = value * 10 + (text[i] - '0');
  }
  return value;
}

bool char_at(std::string_view text, std::size_t pos, char c) {
  return pos < text.size() && text[pos] == c;
}

struct Fields {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0;
  double second = 0.0;
};

/// `YYYY-MM-DD?HH:MM` at the start; the error says which part is malformed.
std::optional<std::string> read_date_time(std::string_view text, Fields& f) {
  const auto year = digits_at(text, 0, 4);
  if (!year || !char_at(text, 4, '-')) return "expected a 4-digit year and '-'";
  const auto month = digits_at(text, 5, 2);
  if (!month || !char_at(text, 7, '-')) return "expected a 2-digit month and '-' after the year";
  const auto day = digits_at(text, 8, 2);
  if (!day) return "expected a 2-digit day after the month";
  if (!char_at(text, 10, 'T') && !char_at(text, 10, ' ')) {
    return "expected 'T' or ' ' between the date and the time";
  }
  const auto hour = digits_at(text, 11, 2);
  if (!hour || !char_at(text, 13, ':')) return "expected a 2-digit hour and ':'";
  const auto minute = digits_at(text, 14, 2);
  if (!minute) return "expected 2-digit minutes after the hour";
  f = Fields{*year, *month, *day, *hour, *minute, 0.0};
  return std::nullopt;
}

/// Optional `:SS[.fff...]` at `pos`; advances `pos` past it.
std::optional<std::string> read_seconds(std::string_view text, std::size_t& pos, Fields& f) {
  if (!char_at(text, pos, ':')) return std::nullopt;
  const std::size_t start = pos + 1;
  const auto whole = digits_at(text, start, 2);
  if (!whole) return "expected 2-digit seconds after ':'";
  pos = start + 2;
  if (char_at(text, pos, '.')) {
    ++pos;
    const std::size_t frac_start = pos;
    while (pos < text.size() && is_digit(text[pos])) ++pos;
    if (pos == frac_start) return "expected digits after the decimal point";
  }
  if (*whole == 60) return "leap-second instants (23:59:60) are not supported";
  const char* first = text.data() + start;
  const auto [end, ec] = std::from_chars(first, text.data() + pos, f.second);
  if (ec != std::errc{} || end != text.data() + pos) return "unreadable seconds";
  // "59.99999999999999999" rounds to 60.0 as a double: keep it inside the minute.
  if (*whole <= 59 && f.second >= 60.0) f.second = std::nextafter(60.0, 0.0);
  return std::nullopt;
}

std::optional<std::string> check_zone(std::string_view zone) {
  if (zone == "Z" || zone == "+00:00" || zone == "+0000") return std::nullopt;
  if (zone.empty()) return "no time zone: append 'Z' (or +00:00) for UTC";
  if (zone.front() == '+' || zone.front() == '-') {
    return "offset " + quote(zone) + " is not UTC: only Z, +00:00 or +0000 are accepted";
  }
  return "unexpected " + quote(zone) + " after the time";
}

/// Appends `value` (>= 0) with at least `width` digits.
void append_padded(std::string& out, std::int64_t value, std::size_t width) {
  char buf[24];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  const auto len = static_cast<std::size_t>(end - buf);
  if (ec != std::errc{}) return;
  if (len < width) out.append(width - len, '0');
  out.append(buf, len);
}

}  // namespace

Result<UtcInstant> parse_iso8601_utc(std::string_view text) {
  Fields f;
  if (auto why = read_date_time(text, f)) return bad(text, *why);
  std::size_t pos = 16;
  if (auto why = read_seconds(text, pos, f)) return bad(text, *why);
  if (auto why = check_zone(text.substr(pos))) return bad(text, *why);
  auto instant = UtcInstant::from_calendar(f.year, f.month, f.day, f.hour, f.minute, f.second);
  if (!instant) return bad(text, instant.error().message);
  return instant;
}

std::string format_iso8601_utc_unix(double unix_s) {
  return format_iso8601_utc(UtcInstant::from_unix_seconds(unix_s));
}

std::string format_iso8601_utc(const UtcInstant& t) {
  int year = 0, month = 0, day = 0;
  double fraction_of_day = 0.0;
  if (!std::isfinite(t.jd.jd1) || !std::isfinite(t.jd.jd2) ||
      eraJd2cal(t.jd.jd1, t.jd.jd2, &year, &month, &day, &fraction_of_day) != 0) {
    return "(invalid UTC instant)";
  }
  auto ms =
      static_cast<std::int64_t>(std::llround(fraction_of_day * static_cast<double>(kMsPerDay)));
  if (ms >= kMsPerDay) {  // 23:59:59.9996 rounds to 00:00:00.000 of the next day
    ms -= kMsPerDay;
    double djm0 = 0.0;
    double djm = 0.0;
    double unused = 0.0;
    eraCal2jd(year, month, day, &djm0, &djm);
    eraJd2cal(djm0, djm + 1.0, &year, &month, &day, &unused);
  }
  std::string out;
  out.reserve(24);
  if (year < 0) out += '-';
  append_padded(out, std::abs(year), 4);
  out += '-';
  append_padded(out, month, 2);
  out += '-';
  append_padded(out, day, 2);
  out += 'T';
  append_padded(out, ms / 3'600'000, 2);
  out += ':';
  append_padded(out, ms / 60'000 % 60, 2);
  out += ':';
  append_padded(out, ms / 1000 % 60, 2);
  out += '.';
  append_padded(out, ms % 1000, 3);
  out += 'Z';
  return out;
}

}  // namespace azt::astro
