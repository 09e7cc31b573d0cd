#include "azt/calibration/power_feed.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace azt::calibration {
namespace {

constexpr double kDefaultStaleS = 2.0;

PowerFeedSettings sane(PowerFeedSettings settings) {
  if (!(std::isfinite(settings.stale_s) && settings.stale_s > 0.0)) {
    settings.stale_s = kDefaultStaleS;
  }
  settings.history = std::clamp<std::size_t>(settings.history, 1, kPowerFeedMaxHistory);
  return settings;
}

bool before(const PowerReading& reading, double t_s) { return reading.t_s < t_s; }
bool after(double t_s, const PowerReading& reading) { return t_s < reading.t_s; }

}  // namespace

PowerFeed::PowerFeed(PowerFeedSettings settings) : settings_(sane(settings)) {}

void PowerFeed::accept(double now_s, double power_db) {
  if (!std::isfinite(power_db)) return malformed(now_s, "power is not a finite number");
  if (!std::isfinite(now_s)) return malformed(now_s, "reading without a valid time");
  if (!readings_.empty()) now_s = std::max(now_s, readings_.back().t_s);
  readings_.push_back(PowerReading{now_s, power_db});
  while (readings_.size() > settings_.history) readings_.pop_front();
  ++counts_.good;
  silence_counted_ = false;  // a reading ends the silence; the next one counts again
}

void PowerFeed::malformed(double now_s, std::string reason) {
  ++counts_.malformed;
  if (reason.size() > kPowerFeedMaxReasonChars) {
    reason.resize(kPowerFeedMaxReasonChars);
    reason += "...";
  }
  last_reason_ = std::move(reason);
  last_malformed_s_ = std::isfinite(now_s) ? std::optional<double>(now_s) : std::nullopt;
}

bool PowerFeed::stale(double now_s) const {
  // Written so a NaN now_s reads as stale: no reading can be shown fresh at no time.
  return readings_.empty() || !(now_s - readings_.back().t_s <= settings_.stale_s);
}

std::optional<PowerReading> PowerFeed::latest(double now_s) const {
  if (!stale(now_s)) return readings_.back();
  if (!silence_counted_) {
    silence_counted_ = true;
    ++missing_;
  }
  return std::nullopt;
}

std::vector<PowerReading> PowerFeed::readings_between(double from_s, double to_s) const {
  if (!(from_s <= to_s)) return {};
  // The history is in time order (accept() keeps it so): two binary searches.
  const auto first = std::lower_bound(readings_.begin(), readings_.end(), from_s, before);
  const auto last = std::upper_bound(first, readings_.end(), to_s, after);
  return {first, last};
}

std::vector<PowerReading> PowerFeed::readings_since(double from_s) const {
  if (std::isnan(from_s)) return {};
  const auto first = std::lower_bound(readings_.begin(), readings_.end(), from_s, before);
  return {first, readings_.end()};
}

PowerFeedCounts PowerFeed::counts() const {
  PowerFeedCounts counts = counts_;
  counts.missing = missing_;
  return counts;
}

std::optional<double> mean_power_db(std::span<const PowerReading> readings) {
  if (readings.empty()) return std::nullopt;
  // Relative to the strongest reading so 10^(dB/10) stays in range for any finite dB.
  double peak_db = readings.front().power_db;
  for (const PowerReading& r : readings) peak_db = std::max(peak_db, r.power_db);
  double sum = 0.0;
  for (const PowerReading& r : readings) sum += std::pow(10.0, (r.power_db - peak_db) / 10.0);
  return peak_db + 10.0 * std::log10(sum / static_cast<double>(readings.size()));
}

}  // namespace azt::calibration
