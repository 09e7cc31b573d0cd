#pragma once

#include <string>
#include <string_view>

#include "azt/astro/leap_seconds.hpp"
#include "azt/util/result.hpp"

namespace azt::astro {

/// A two-part Julian date (ERFA convention: jd1 + jd2, usually jd1 = 2400000.5 or the day number,
/// jd2 the fraction), which keeps ~20 µs-over-a-century precision at the microsecond level.
struct JulianDate {
  double jd1 = 0.0;
  double jd2 = 0.0;
  [[nodiscard]] double total() const { return jd1 + jd2; }
};

/// A UTC instant. Stored as a two-part Julian date on a uniform 86400 s day: instants inside a
/// positive leap second (23:59:60) cannot be represented and are rejected by the parser.
struct UtcInstant {
  JulianDate jd;
  /// From a calendar date and time (Gregorian, UTC). Error on an impossible date/time or a year
  /// outside 1900..2200.
  static Result<UtcInstant> from_calendar(int year, int month, int day, int hour, int minute,
                                          double second);
  /// From Unix time (seconds since 1970-01-01T00:00:00Z, leap seconds not counted, as POSIX).
  /// Whole days go to jd1 and the time of day to jd2, so sub-microsecond digits survive. A
  /// non-finite input gives a non-finite instant, which make_time_scales() rejects.
  static UtcInstant from_unix_seconds(double unix_s);
  /// Unix time of the instant: the inverse of from_unix_seconds (days and the time of day apart,
  /// so the sub-microsecond digits survive).
  [[nodiscard]] double unix_seconds() const;
  /// Modified Julian Date of the instant (UTC day count + fraction).
  [[nodiscard]] double mjd() const;
};

/// Parses an ISO 8601 UTC instant: `YYYY-MM-DDTHH:MM[:SS[.fff]]Z` (a space may replace the `T`;
/// `+00:00` may replace the `Z`). Anything else — a missing zone, another offset, junk — is an
/// error naming the problem.
Result<UtcInstant> parse_iso8601_utc(std::string_view text);

/// The UTC instant `seconds` after `from` (two-part Julian date arithmetic, no rounding to ms).
UtcInstant utc_plus(const UtcInstant& from, double seconds);

/// Formats as `YYYY-MM-DDTHH:MM:SS.sssZ` (milliseconds, rounded; 23:59:59.9996 carries into the
/// next day). A non-finite instant, or one ERFA's calendar cannot hold, formats as
/// "(invalid UTC instant)", which the parser rejects.
std::string format_iso8601_utc(const UtcInstant& t);
/// The same for an instant in Unix seconds (UTC seconds since 1970), as the daemon's clock and
/// its JSON hold instants.
std::string format_iso8601_utc_unix(double unix_s);

/// The time scales the sky needs at one instant.
struct TimeScales {
  UtcInstant utc;
  JulianDate tt;   ///< Terrestrial Time = TAI + 32.184 s (used as TDB: differs by < 2 ms).
  JulianDate ut1;  ///< UT1 = UTC + DUT1.
  double tai_minus_utc_s = 0.0;
  double dut1_s = 0.0;
  /// True when the instant lies after the leap-second table's expiry date: TAI−UTC is then the
  /// last known value and may be wrong by whole seconds if a leap second was announced since.
  bool leap_table_expired = false;
};

/// Limits for DUT1 = UT1 − UTC: IERS keeps |DUT1| < 0.9 s; larger values (up to ±10 s) are
/// accepted for comparisons with programs that use their own ΔT models, and flagged by callers.
inline constexpr double kDut1NominalLimitS = 0.9;
inline constexpr double kDut1HardLimitS = 10.0;

/// Builds TT and UT1 for a UTC instant. Errors: DUT1 non-finite or beyond ±10 s; instant before
/// 1972-01-01 (start of the leap-second table).
Result<TimeScales> make_time_scales(const UtcInstant& utc, double dut1_s,
                                    const LeapSecondTable& table);

}  // namespace azt::astro
