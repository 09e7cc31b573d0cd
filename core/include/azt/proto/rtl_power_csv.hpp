#pragma once
// rtl_power's CSV output (Debian package rtl-sdr), one line at a time: the receiver power input
// for pointing scans (docs/calibration.md). rtl_power.c's csv_dbm() prints, per hop of a sweep,
//
//   2024-01-02, 12:34:56, 1296000000, 1296500000, 1953.12, 10, -42.10, -41.90, ..., -41.95
//
// that is strftime "%Y-%m-%d, %H:%M:%S" (local time, whole seconds), then "%i, %i, %.2f, %i, "
// for Hz low, Hz high, Hz step and the number of samples averaged, then one "%.2f" dB value per
// frequency bin, comma-and-space separated, ending in "\n". (The last bin repeats the one before
// it: a quirk of rtl_power.c, harmless for the band's total power.) The three Hz fields are read
// as decimals, so tools that copy the format with fractional Hz are read too.
//
// A range wider than the tuner's bandwidth is swept in hops, one line per hop with the same
// timestamp; a pointing scan measures one band, so it configures a range that fits one hop
// (for example `rtl_power -f 1296M:1296.5M:2k -i 1`) and each line is one reading.
//
// Strict, as every codec here (docs/architecture.md): numbers are read locale-free with from_chars,
// only spaces (and tabs) after a comma and one trailing "\r" are tolerated, and a field that is
// empty, not a number, or followed by junk makes the whole line malformed. The date and time are
// not used (the feed stamps each reading when it arrives, on the daemon's clock); they are only
// checked to be non-empty and made of digits and '-' (date) or digits, ':' and '.' (time).
//
// A bin rtl_power prints as "nan", "-nan", "inf" or "-inf" (log10 of an empty or zero bin: no
// samples, or a dead tuner) makes the line malformed rather than being skipped or read as zero
// power: such a sweep did not measure the band, and a scan must count it as a missing reading,
// not as a deep null that would pull the fitted beam.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "azt/util/result.hpp"

namespace azt::proto {

/// More bins than this is a flood, not a scan reading (a pointing scan's hop has a few thousand
/// bins at most); the line is refused before more are stored.
inline constexpr std::size_t kRtlPowerMaxBins = 100000;
/// Bins outside ±this many dB are refused: rtl_power's values are tens of dB around 0, and the
/// bound keeps 10^(dB/10) finite in sweep_power_db.
inline constexpr double kRtlPowerMaxAbsBinDb = 300.0;

struct RtlPowerSweep {
  double hz_low = 0.0;          ///< lower edge of the hop, Hz
  double hz_high = 0.0;         ///< upper edge, Hz (>= hz_low)
  double hz_step = 0.0;         ///< bin width, Hz (> 0)
  std::int64_t samples = 0;     ///< samples averaged into each bin (>= 0)
  std::vector<double> bins_db;  ///< one power per bin, dB (rtl_power's uncalibrated scale)
};

/// Parses one line of rtl_power's CSV output (without or with its "\n" or "\r\n"). Pure.
Result<RtlPowerSweep> parse_rtl_power_line(std::string_view line);

/// The total power across the hop, dB: 10·log10 of the mean of 10^(bin/10). Averaged in linear
/// units, because power adds and dB do not (the mean of −10 and −20 dB is −12.6 dB, not −15 dB).
/// NaN for a sweep without bins (parse_rtl_power_line never returns one).
double sweep_power_db(const RtlPowerSweep& sweep);

}  // namespace azt::proto
