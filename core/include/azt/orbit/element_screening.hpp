#pragma once
// Whether a download of element sets may replace what a source gave before, and the catalogue
// the station uses, merged from every source (docs/satellites.md, "Elements from the network").
//
// A download is refused whole, never in part: a transfer cut short, a server error page, an
// upstream mistake or a cache serving last week's file would otherwise reach the catalogue
// entry by entry (the failures Gpredict, SatDump and Stellarium users met when CelesTrak moved
// its files: round3 notes §4.4). The previous sets of the source stay in use.
//
// Pure: the time is a parameter, nothing here reads a clock or a file.

#include <cstddef>
#include <string>
#include <vector>

#include "azt/orbit/elements.hpp"

namespace azt::orbit {

struct ScreeningLimits {
  /// An epoch further ahead of now than this is garbage or a wrong clock: CelesTrak's GP epochs
  /// are in the past, supplemental (SupGP) ones at most hours ahead.
  double max_future_days = 3.0;
  /// An epoch older than this is no element set anyone serves for tracking (a garbled year
  /// reads as 1957–1999 or a date decades back).
  double max_age_days = 3650.0;
  /// Fewer sets than this fraction of the source's previous download is a truncated or broken
  /// upstream file, not the sky changing.
  double min_count_ratio = 0.1;
};

/// A download as read: its good sets and one message per entry that did not parse (a TLE's
/// checksum, an OMM keyword), as the element-set readers give them.
struct ElementDownload {
  std::vector<Elements> sets;
  std::vector<std::string> errors;
};

/// The verdict: `refusal` empty when the download may be used.
struct Screening {
  std::string refusal;
  [[nodiscard]] bool accepted() const { return refusal.empty(); }
};

/// Checks a download against the source's previous accepted sets (`previous`, empty for a first
/// download) at `now_unix_s`. Refused: nothing in it; any entry that did not parse; an epoch more
/// than max_future_days ahead or max_age_days behind; fewer than min_count_ratio of the previous
/// count; any satellite whose epoch is older than the one the source gave before. The refusal
/// names the first case found, with the satellite and the epochs where there is one.
Screening screen_download(const ElementDownload& download, const std::vector<Elements>& previous,
                          double now_unix_s, const ScreeningLimits& limits = {});

/// The same epoch checks for a file the operator gives (an upload, `[satellites] file`), where
/// no count or history applies: the first entry beyond the limits, or empty.
std::string implausible_epoch(const std::vector<Elements>& sets, double now_unix_s,
                              const ScreeningLimits& limits = {});

/// The NORAD number as a key: leading zeros dropped ("07276" and "7276" are one satellite).
std::string norad_key(const std::string& catalog);
/// The epoch as one Julian date (for comparisons; days).
double epoch_jd(const Elements& e);
/// The epoch as Unix seconds.
double epoch_unix_s(const Elements& e);

/// One catalogue from several sources: per NORAD number the set with the newest epoch (a tie
/// goes to the earlier source), in the order each number first appears.
std::vector<Elements> merge_newest(const std::vector<const std::vector<Elements>*>& sources);

}  // namespace azt::orbit
