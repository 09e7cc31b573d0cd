#pragma once
// What chronyd says about the clock, as `chronyc -c tracking` and `chronyc -c -n sources` print
// it (docs/time.md): comma-separated values, one report per line, fields in the order of the
// human-readable reports (chronyc(1), "tracking" and "sources"). Pure parsers: the Linux side
// runs chronyc and hands the text here, so every malformed line is a tested error, not a crash.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "azt/util/result.hpp"

namespace azt::timekeeping {

/// `chronyc -c tracking`: the reference the system clock follows and how well.
struct ChronyTracking {
  std::string ref_id_hex;        ///< "47505300" for a refclock with refid GPS
  std::string ref_name;          ///< the source's name or address; the refid's text for a refclock
  int stratum = 0;               ///< 0 before any source has been selected
  double ref_time_unix_s = 0.0;  ///< when the reference was last updated (0: never)
  /// The system clock minus true time now, in seconds (positive: fast). chronyc's "System
  /// time" is the correction still to apply, the opposite sign.
  double system_offset_s = 0.0;
  double last_offset_s = 0.0;  ///< the offset measured at the last update
  double rms_offset_s = 0.0;
  double frequency_ppm = 0.0;
  double root_delay_s = 0.0;
  double root_dispersion_s = 0.0;
  double update_interval_s = 0.0;
  std::string leap;  ///< "Normal", "Insert second", "Delete second", "Not synchronised"

  /// chronyd has a reference and the leap status is known.
  [[nodiscard]] bool synchronised() const;
};

/// One line of `chronyc -c -n sources`.
struct ChronySource {
  char mode = '?';   ///< '^' server, '=' peer, '#' reference clock
  char state = '?';  ///< '*' selected, '+' combined, '-' not combined, '?' unusable, 'x' false
                     ///< ticker, '~' too variable
  std::string name;  ///< address, or a refclock's refid
  int stratum = 0;
  int poll_log2_s = 0;              ///< the polling interval is 2^poll seconds
  int reach = 0;                    ///< the last eight polls as bits (chronyc prints octal)
  std::optional<double> last_rx_s;  ///< seconds since the last sample; none: never
  double offset_s = 0.0;            ///< the adjusted offset of the last sample
  double measured_offset_s = 0.0;
  double error_s = 0.0;  ///< the error bound of the last sample
};

/// "server", "peer", "refclock", or "unknown".
std::string_view mode_name(char mode);
/// "selected", "combined", "not_combined", "unusable", "falseticker", "too_variable", "unknown".
std::string_view state_name(char state);

/// The first line of `chronyc -c tracking`; an error naming the field that did not parse.
Result<ChronyTracking> parse_chrony_tracking(std::string_view csv);
/// Every line of `chronyc -c -n sources` (none is fine: no sources); an error names the line.
Result<std::vector<ChronySource>> parse_chrony_sources(std::string_view csv);

}  // namespace azt::timekeeping
