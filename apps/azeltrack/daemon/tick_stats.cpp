#include "daemon/tick_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace azt::app {

void TickStats::add(double late_s) {
  late_s = std::max(0.0, late_s);
  const auto bin = static_cast<std::size_t>(std::min(late_s / kBinS, static_cast<double>(kBins)));
  ++bins_[bin];
  ++count_;
  max_s_ = std::max(max_s_, late_s);
}

double TickStats::quantile(double q) const {
  if (count_ == 0) return 0.0;
  const auto wanted = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < bins_.size(); ++i) {
    seen += bins_[i];
    if (seen >= std::max<std::uint64_t>(wanted, 1)) return static_cast<double>(i + 1) * kBinS;
  }
  return max_s_;
}

std::string TickStats::summary() const {
  char text[160];
  std::snprintf(text, sizeof text,
                "ticks %llu, late p50 %.3f ms p99 %.3f ms max %.3f ms, %llu overruns",
                static_cast<unsigned long long>(count_), quantile(0.5) * 1e3, quantile(0.99) * 1e3,
                max_s_ * 1e3, static_cast<unsigned long long>(overruns_));
  return text;
}

}  // namespace azt::app
