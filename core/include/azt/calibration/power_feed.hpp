#pragma once
// The receiver power readings as they arrive (docs/calibration.md: malformed or missing readings
// are counted and shown), whatever carried them: an rtl_power sweep, a UDP datagram, a line on a
// pipe. The adapter that reads the feed stamps each reading with the daemon's monotonic clock and
// hands it here; a scan then asks for the latest reading, or for the readings that fell inside a
// point's dwell window. Pure: time is a parameter (docs/architecture.md), seconds on one steady
// clock; everything is bounded (the recent readings, the last error's text).
//
// The three counters:
//   good       readings accepted;
//   malformed  lines or datagrams the adapter could not parse (malformed()), and readings handed
//              to accept() that are not finite;
//   missing    silences a consumer noticed: latest() finding the feed stale (no reading within
//              stale_s, or none yet) counts one, and then no more until a reading arrives. So a
//              feed that stops for a minute while a scan polls it every tick counts one missing,
//              not 600, and a silence nobody asked about (no scan running) counts none.
// latest() is const because it changes no reading; the silence it notices is bookkeeping, like a
// cache's hit counter. stale() asks the same question without counting, for a status display.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace azt::calibration {

/// The most readings a feed keeps: 4096 is over 6 minutes at 10 readings a second, longer than
/// any dwell, at 64 KiB.
inline constexpr std::size_t kPowerFeedMaxHistory = 4096;
/// The last malformed reason is cut to this many characters.
inline constexpr std::size_t kPowerFeedMaxReasonChars = 200;

struct PowerFeedSettings {
  /// A reading older than this is no reading. Not a positive finite number: 2 s is used.
  double stale_s = 2.0;
  /// Recent readings kept for readings_between(); clamped to 1..kPowerFeedMaxHistory.
  std::size_t history = kPowerFeedMaxHistory;
};

struct PowerReading {
  double t_s = 0.0;       ///< when it arrived, on the caller's steady clock
  double power_db = 0.0;  ///< dB on the receiver's own (uncalibrated) scale
  bool operator==(const PowerReading&) const = default;
};

struct PowerFeedCounts {
  std::uint64_t good = 0;
  std::uint64_t malformed = 0;
  std::uint64_t missing = 0;
  bool operator==(const PowerFeedCounts&) const = default;
};

class PowerFeed {
 public:
  explicit PowerFeed(PowerFeedSettings settings = {});

  /// A parsed reading that arrived at `now_s`. A time earlier than the newest reading's (a
  /// caller mixing clocks) is taken as the newest's, so the history stays in time order. A power
  /// that is not finite is counted as malformed instead.
  void accept(double now_s, double power_db);
  /// A line or datagram that held no valid reading; `reason` is kept (cut short) for display.
  void malformed(double now_s, std::string reason);

  /// The newest reading, or nullopt when there is none or it is older than stale_s at `now_s`
  /// (exactly stale_s old is still fresh). Counts a missing at the start of a silence (header).
  std::optional<PowerReading> latest(double now_s) const;
  /// Whether latest(now_s) would find nothing; counts nothing.
  [[nodiscard]] bool stale(double now_s) const;

  /// The kept readings with from_s <= t_s <= to_s, oldest first (a scan point's dwell window).
  [[nodiscard]] std::vector<PowerReading> readings_between(double from_s, double to_s) const;
  /// The kept readings with t_s >= from_s, oldest first.
  [[nodiscard]] std::vector<PowerReading> readings_since(double from_s) const;

  [[nodiscard]] PowerFeedCounts counts() const;
  /// Why the last malformed reading was refused; empty when none was.
  [[nodiscard]] const std::string& last_malformed_reason() const { return last_reason_; }
  /// When it arrived; nullopt when none was.
  [[nodiscard]] std::optional<double> last_malformed_s() const { return last_malformed_s_; }
  /// Readings kept now (at most settings().history).
  [[nodiscard]] std::size_t size() const { return readings_.size(); }
  [[nodiscard]] const PowerFeedSettings& settings() const { return settings_; }

 private:
  PowerFeedSettings settings_;
  std::deque<PowerReading> readings_;
  PowerFeedCounts counts_;  ///< good and malformed; missing is missing_
  std::string last_reason_;
  std::optional<double> last_malformed_s_;
  /// The bookkeeping latest() does (see the header): the current silence is already counted.
  mutable bool silence_counted_ = false;
  mutable std::uint64_t missing_ = 0;
};

/// The mean power of `readings`, dB, averaged in linear units (power adds, dB do not: the mean
/// of −10 and −20 dB is −12.6 dB); nullopt when there are none.
std::optional<double> mean_power_db(std::span<const PowerReading> readings);

}  // namespace azt::calibration
