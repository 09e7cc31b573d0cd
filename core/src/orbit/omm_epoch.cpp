// OMM EPOCH text → the split UTC Julian date of the TLE parser (tle_epoch_to_jd): whole = Vallado's
// jday at 0 h of the date, fraction = time of day / 86400, so a TLE and its OMM give SGP4 the same
// start. CCSDS 502.0-B-3 §7.5.10 allows the calendar form and the day-of-year form; both are read.

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "azt/orbit/omm_record.hpp"
#include "azt/util/parse_number.hpp"

namespace azt::orbit {

namespace {

/// Element sets exist from Sputnik on; Vallado's jday formula holds until 2100-02-28.
constexpr int kMinYear = 1957;
constexpr int kMaxYear = 2099;
/// Decimals of the seconds read (CelesTrak prints 6); more would be noise below a picosecond.
constexpr std::size_t kMaxDecimals = 12;

struct Calendar {
  int year = 0;
  int month = 0;
  int day = 0;
  int hour = 0;
  int minute = 0;
  double second = 0.0;  ///< with its decimals
};

/// Reads an epoch left to right; every call consumes only what it accepts.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : text_(text) {}

  /// Exactly `count` digits as a number, or nothing (and nothing consumed).
  std::optional<int> digits(std::size_t count) {
    if (digit_run() < count) return std::nullopt;
    int value = 0;
    for (std::size_t i = 0; i < count; ++i) value = value * 10 + (text_[pos_ + i] - '0');
    pos_ += count;
    return value;
  }

  bool literal(char c) {
    if (pos_ >= text_.size() || text_[pos_] != c) return false;
    ++pos_;
    return true;
  }

  [[nodiscard]] std::size_t digit_run() const {
    std::size_t n = 0;
    while (pos_ + n < text_.size() && text_[pos_ + n] >= '0' && text_[pos_ + n] <= '9') ++n;
    return n;
  }

  std::string_view take(std::size_t count) {
    const std::string_view taken = text_.substr(pos_, count);
    pos_ += taken.size();
    return taken;
  }

  [[nodiscard]] bool at_end() const { return pos_ == text_.size(); }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

Error bad_shape(std::string_view text) {
  constexpr std::size_t kShown = 40;
  return fail("'" + std::string(text.substr(0, kShown)) +
              "' is not YYYY-MM-DDThh:mm:ss[.ffffff] or YYYY-DDDThh:mm:ss[.ffffff]");
}

bool is_leap(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int days_in_month(int year, int month) {
  constexpr std::array<int, 13> kDays = {0, 31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap(year) ? 29 : kDays.at(static_cast<std::size_t>(month));
}

/// "-MM-DD" or "-DDD" after the year: month and day either way.
Result<bool> read_date(Cursor& cursor, Calendar& t, std::string_view text) {
  if (cursor.digit_run() == 3) {
    const int day_of_year = *cursor.digits(3);
    const int year_days = is_leap(t.year) ? 366 : 365;
    if (day_of_year < 1 || day_of_year > year_days) {
      return fail("day of year " + std::to_string(day_of_year) + " out of range 1–" +
                  std::to_string(year_days));
    }
    t.month = 1;
    t.day = day_of_year;
    while (t.day > days_in_month(t.year, t.month)) t.day -= days_in_month(t.year, t.month++);
    return true;
  }
  const std::optional<int> month = cursor.digits(2);
  if (!month || !cursor.literal('-')) return bad_shape(text);
  const std::optional<int> day = cursor.digits(2);
  if (!day || cursor.digit_run() > 0) return bad_shape(text);
  if (*month < 1 || *month > 12)
    return fail("month " + std::to_string(*month) + " out of range 1–12");
  const int month_days = days_in_month(t.year, *month);
  if (*day < 1 || *day > month_days) {
    return fail("day " + std::to_string(*day) + " out of range 1–" + std::to_string(month_days));
  }
  t.month = *month;
  t.day = *day;
  return true;
}

/// "Thh:mm:ss[.f…][Z]" to the end of the text.
Result<bool> read_time(Cursor& cursor, Calendar& t, std::string_view text) {
  std::optional<int> hour;
  std::optional<int> minute;
  std::optional<int> second;
  if (cursor.literal('T')) hour = cursor.digits(2);
  if (hour && cursor.literal(':')) minute = cursor.digits(2);
  if (minute && cursor.literal(':')) second = cursor.digits(2);
  if (!second) return bad_shape(text);
  double decimals = 0.0;
  if (cursor.literal('.')) {
    const std::size_t count = cursor.digit_run();
    if (count == 0 || count > kMaxDecimals) return bad_shape(text);
    decimals = parse_finite_double("0." + std::string(cursor.take(count))).value_or(0.0);
  }
  cursor.literal('Z');
  if (!cursor.at_end()) return bad_shape(text);
  // 23:59:60 is a leap second, the only 60 UTC has.
  const bool leap_second = *second == 60 && *hour == 23 && *minute == 59;
  if (*hour > 23 || *minute > 59 || (*second > 59 && !leap_second)) {
    return fail("time of day " + std::string(text.substr(text.find('T') + 1, 8)) + " out of range");
  }
  t.hour = *hour;
  t.minute = *minute;
  t.second = *second + decimals;
  return true;
}

Result<Calendar> parse_calendar(std::string_view text) {
  Cursor cursor(text);
  Calendar t;
  const std::optional<int> year = cursor.digits(4);
  if (!year || cursor.digit_run() > 0 || !cursor.literal('-')) return bad_shape(text);
  t.year = *year;
  if (t.year < kMinYear || t.year > kMaxYear) {
    return fail("year " + std::to_string(t.year) + " out of range " + std::to_string(kMinYear) +
                "–" + std::to_string(kMaxYear));
  }
  if (Result<bool> ok = read_date(cursor, t, text); !ok) return ok.error();
  if (Result<bool> ok = read_time(cursor, t, text); !ok) return ok.error();
  return t;
}

}  // namespace

Result<JulianDate> parse_omm_epoch(std::string_view text) {
  Result<Calendar> parsed = parse_calendar(text);
  if (!parsed) return parsed.error();
  const Calendar& t = *parsed;
  // Vallado's jday in its split form, term for term as tle_epoch_to_jd (core/src/orbit/tle.cpp)
  // computes it, so the two parsers agree to the last bit on the whole part.
  JulianDate jd;
  jd.whole = 367.0 * t.year - std::floor((7 * (t.year + std::floor((t.month + 9) / 12.0))) * 0.25) +
             std::floor(275 * t.month / 9.0) + t.day + 1721013.5;
  jd.fraction = (t.second + t.minute * 60.0 + t.hour * 3600.0) / 86400.0;
  if (jd.fraction >= 1.0) {  // only inside a leap second
    jd.whole += 1.0;
    jd.fraction -= 1.0;
  }
  return jd;
}

}  // namespace azt::orbit
