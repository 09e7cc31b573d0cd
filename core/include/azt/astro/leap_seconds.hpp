#pragma once

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "azt/util/result.hpp"

namespace azt::astro {

/// TAI − UTC since 1972, step by step, with the date after which the table is no longer
/// guaranteed (a leap second may have been announced that it does not know about).
class LeapSecondTable {
 public:
  struct Step {
    double mjd_utc = 0.0;          ///< first UTC day (MJD) on which the offset applies
    double tai_minus_utc_s = 0.0;  ///< whole seconds
  };

  /// The table compiled into azeltrack (IERS Bulletin C, last step 2017-01-01 TAI−UTC = 37 s).
  static const LeapSecondTable& builtin();

  /// Parses the IETF/NIST `leap-seconds.list` format that Debian's tzdata installs at
  /// /usr/share/zoneinfo/leap-seconds.list: data lines `NTP_SECONDS  TAI-UTC  # comment`, the
  /// expiry line `#@ NTP_SECONDS`, other `#` lines ignored. Errors name the offending line number:
  /// malformed numbers, steps out of order, an offset that does not change by whole seconds, no
  /// data lines, or no expiry line.
  static Result<LeapSecondTable> parse_ietf_list(std::string_view text);

  /// TAI − UTC (s) on UTC day `mjd_utc`; nullopt before 1972-01-01 (MJD 41317).
  [[nodiscard]] std::optional<double> tai_minus_utc(double mjd_utc) const;

  /// MJD (UTC) after which the table has expired.
  [[nodiscard]] double expiry_mjd() const { return expiry_mjd_; }
  [[nodiscard]] bool expired_at(double mjd_utc) const { return mjd_utc > expiry_mjd_; }
  [[nodiscard]] const std::vector<Step>& steps() const { return steps_; }

  /// `steps` must ascend by date (parse_ietf_list() and builtin() guarantee it).
  LeapSecondTable(std::vector<Step> steps, double expiry_mjd)
      : steps_(std::move(steps)), expiry_mjd_(expiry_mjd) {}

 private:
  std::vector<Step> steps_;
  double expiry_mjd_ = 0.0;
};

}  // namespace azt::astro
