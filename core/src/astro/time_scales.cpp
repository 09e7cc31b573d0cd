#include "azt/astro/time_scales.hpp"
#include "azt/util/format_number.hpp"

#include <erfa.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>

namespace azt::astro {

namespace {

constexpr double kMjdZeroJd = 2400000.5;   ///< JD of MJD 0 (1858-11-17T00:00Z)
constexpr double kUnixEpochMjd = 40587.0;  ///< 1970-01-01
constexpr double kSecondsPerDay = 86400.0;
constexpr double kTtMinusTaiS = 32.184;  ///< IAU 1991 Resolution A4: TT = TAI + 32.184 s
constexpr int kMinYear = 1900;
constexpr int kMaxYear = 2200;

bool is_leap_year(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int days_in_month(int year, int month) {
  constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap_year(year) ? 29 : kDays[month - 1];
}

std::optional<Error> check_calendar(int year, int month, int day, int hour, int minute,
                                    double second) {
  const auto range = [](const char* what, int value, int lo, int hi) {
    return fail(std::string(what) + " " + std::to_string(value) + " is not in " +
                std::to_string(lo) + ".." + std::to_string(hi));
  };
  if (year < kMinYear || year > kMaxYear) return range("year", year, kMinYear, kMaxYear);
  if (month < 1 || month > 12) return range("month", month, 1, 12);
  if (day < 1 || day > days_in_month(year, month)) {
    Error e = range("day", day, 1, days_in_month(year, month));
    e.message +=
        " in " + std::to_string(year) + "-" + (month < 10 ? "0" : "") + std::to_string(month);
    return e;
  }
  if (hour < 0 || hour > 23) return range("hour", hour, 0, 23);
  if (minute < 0 || minute > 59) return range("minute", minute, 0, 59);
  if (!std::isfinite(second) || second < 0.0 || second >= 60.0) {
    return fail("second " + format_number(second) + " is not in [0, 60)");
  }
  return std::nullopt;
}

}  // namespace

Result<UtcInstant> UtcInstant::from_calendar(int year, int month, int day, int hour, int minute,
                                             double second) {
  if (auto err = check_calendar(year, month, day, hour, minute, second)) return *err;
  double djm0 = 0.0;
  double djm = 0.0;
  if (eraCal2jd(year, month, day, &djm0, &djm) != 0) {
    return fail("ERFA rejected the date " + std::to_string(year) + "-" + std::to_string(month) +
                "-" + std::to_string(day));
  }
  // djm0 is 2400000.5 and djm a whole MJD: their sum is exact. The time of day stays in jd2.
  const double seconds_of_day = static_cast<double>(hour * 3600 + minute * 60) + second;
  return UtcInstant{JulianDate{djm0 + djm, seconds_of_day / kSecondsPerDay}};
}

UtcInstant UtcInstant::from_unix_seconds(double unix_s) {
  // Split into whole days and the time of day before dividing, so a 1.7e9 s timestamp keeps its
  // sub-microsecond part. fmod is exact; for negative times the shift into [0, 86400) may round,
  // by less than one ulp of 86400 s (15 ps), which round() absorbs when counting the days.
  double seconds_of_day = std::fmod(unix_s, kSecondsPerDay);
  if (seconds_of_day < 0.0) seconds_of_day += kSecondsPerDay;
  if (seconds_of_day >= kSecondsPerDay) seconds_of_day = 0.0;  // e.g. −1e-12 + 86400 == 86400
  const double whole_days = std::round((unix_s - seconds_of_day) / kSecondsPerDay);
  return UtcInstant{
      JulianDate{kMjdZeroJd + kUnixEpochMjd + whole_days, seconds_of_day / kSecondsPerDay}};
}

UtcInstant utc_plus(const UtcInstant& from, double seconds) {
  UtcInstant t = from;
  t.jd.jd2 += seconds / kSecondsPerDay;
  return t;
}

double UtcInstant::mjd() const { return (jd.jd1 - kMjdZeroJd) + jd.jd2; }

double UtcInstant::unix_seconds() const {
  return (jd.jd1 - kMjdZeroJd - kUnixEpochMjd) * kSecondsPerDay + jd.jd2 * kSecondsPerDay;
}

Result<TimeScales> make_time_scales(const UtcInstant& utc, double dut1_s,
                                    const LeapSecondTable& table) {
  if (!std::isfinite(dut1_s) || std::abs(dut1_s) > kDut1HardLimitS) {
    return fail("DUT1 " + format_number(dut1_s) + " s is outside [" +
                format_number(-kDut1HardLimitS) + ", " + format_number(kDut1HardLimitS) +
                "] s (IERS keeps |DUT1| < " + format_number(kDut1NominalLimitS) + " s)");
  }
  const double mjd = utc.mjd();
  if (!std::isfinite(mjd)) return fail("UTC instant is not a finite date");
  const auto tai_minus_utc_s = table.tai_minus_utc(mjd);
  if (!tai_minus_utc_s) {
    const double first = table.steps().empty() ? 0.0 : table.steps().front().mjd_utc;
    return fail("UTC MJD " + format_number(mjd) + " is before the leap-second table starts (MJD " +
                format_number(first) + "; UTC with leap seconds began 1972-01-01 = MJD 41317)");
  }
  TimeScales out;
  out.utc = utc;
  out.tai_minus_utc_s = *tai_minus_utc_s;
  out.dut1_s = dut1_s;
  // Offsets go into the small part so the two-part date keeps its precision.
  out.tt = JulianDate{utc.jd.jd1, utc.jd.jd2 + (*tai_minus_utc_s + kTtMinusTaiS) / kSecondsPerDay};
  out.ut1 = JulianDate{utc.jd.jd1, utc.jd.jd2 + dut1_s / kSecondsPerDay};
  out.leap_table_expired = table.expired_at(mjd);
  return out;
}

}  // namespace azt::astro
