// Screening and merging of downloaded element sets (azt/orbit/element_screening.hpp).
#include "azt/orbit/element_screening.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <unordered_map>

#include "azt/astro/time_scales.hpp"

namespace azt::orbit {
namespace {

constexpr double kUnixEpochJd = 2440587.5;
constexpr double kSecondsPerDay = 86400.0;
/// Epochs equal within this are the same (a cache's round trip, two readers' rounding).
constexpr double kSameEpochDays = 1e-3 / kSecondsPerDay;

std::string when(const Elements& e) { return astro::format_iso8601_utc_unix(epoch_unix_s(e)); }

std::string whole(double value) { return std::to_string(std::lround(value)); }

std::string count_refusal(std::size_t count, std::size_t previous, double ratio) {
  if (previous == 0 || static_cast<double>(count) >= ratio * static_cast<double>(previous)) {
    return "";
  }
  return "suspicious: " + std::to_string(count) + " element sets where the last download had " +
         std::to_string(previous) + " (under " + whole(ratio * 100.0) + " %)";
}

std::string backwards_refusal(const std::vector<Elements>& sets,
                              const std::vector<Elements>& previous) {
  std::unordered_map<std::string, const Elements*> before;
  before.reserve(previous.size());
  for (const Elements& e : previous) before[norad_key(e.catalog)] = &e;
  for (const Elements& e : sets) {
    const auto it = before.find(norad_key(e.catalog));
    if (it == before.end() || epoch_jd(e) >= epoch_jd(*it->second) - kSameEpochDays) continue;
    return "went back in time: " + e.label() + " has epoch " + when(e) + ", older than the " +
           when(*it->second) + " of the last download";
  }
  return "";
}

}  // namespace

std::string norad_key(const std::string& catalog) {
  const std::size_t first = catalog.find_first_not_of('0');
  return first == std::string::npos ? std::string("0") : catalog.substr(first);
}

double epoch_jd(const Elements& e) { return e.epoch_jd + e.epoch_jd_frac; }

double epoch_unix_s(const Elements& e) {
  // Apart, so the time of day keeps its digits: whole days first, then the fraction.
  return ((e.epoch_jd - kUnixEpochJd) + e.epoch_jd_frac) * kSecondsPerDay;
}

std::string implausible_epoch(const std::vector<Elements>& sets, double now_unix_s,
                              const ScreeningLimits& limits) {
  for (const Elements& e : sets) {
    const double age_days = (now_unix_s - epoch_unix_s(e)) / kSecondsPerDay;
    if (age_days < -limits.max_future_days) {
      return "implausible epoch: " + e.label() + " has " + when(e) + ", " + whole(-age_days) +
             " days ahead of the clock (more than " + whole(limits.max_future_days) + ")";
    }
    if (age_days > limits.max_age_days) {
      return "implausible epoch: " + e.label() + " has " + when(e) + ", " + whole(age_days) +
             " days old (more than " + whole(limits.max_age_days) + ")";
    }
  }
  return "";
}

Screening screen_download(const ElementDownload& download, const std::vector<Elements>& previous,
                          double now_unix_s, const ScreeningLimits& limits) {
  if (!download.errors.empty()) {
    const std::size_t more = download.errors.size() - 1;
    return {"does not parse: " + download.errors.front() +
            (more > 0 ? " (and " + std::to_string(more) + " more)" : "")};
  }
  if (download.sets.empty()) return {"no element sets in it"};
  if (std::string why = implausible_epoch(download.sets, now_unix_s, limits); !why.empty()) {
    return {why};
  }
  if (std::string why =
          count_refusal(download.sets.size(), previous.size(), limits.min_count_ratio);
      !why.empty()) {
    return {why};
  }
  return {backwards_refusal(download.sets, previous)};
}

std::vector<Elements> merge_newest(const std::vector<const std::vector<Elements>*>& sources) {
  std::vector<Elements> merged;
  std::unordered_map<std::string, std::size_t> index;
  for (const std::vector<Elements>* source : sources) {
    if (source == nullptr) continue;
    for (const Elements& e : *source) {
      const auto [it, inserted] = index.try_emplace(norad_key(e.catalog), merged.size());
      if (inserted) {
        merged.push_back(e);
      } else if (epoch_jd(e) > epoch_jd(merged[it->second]) + kSameEpochDays) {
        merged[it->second] = e;
      }
    }
  }
  return merged;
}

}  // namespace azt::orbit
