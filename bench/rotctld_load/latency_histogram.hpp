#pragma once
// rotctld_load's latency histogram: values below 1024 ns have their own bucket; above, each octave
// [2^k, 2^k+1) is split into 512 buckets, so a bucket is at most 1/512 of its value wide (< 0.2 %
// error). Memory is bounded however long the run; the max is exact.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace rotctld_load {

class LatencyHistogram {
 public:
  void add(std::uint64_t ns) {
    ns = std::min(ns, kMaxValueNs);
    ++counts_[index_of(ns)];
    ++count_;
    max_ns_ = std::max(max_ns_, ns);
  }
  std::uint64_t count() const { return count_; }
  std::uint64_t max_ns() const { return max_ns_; }
  // The q-quantile (0 < q <= 1), as the middle of its bucket; 0 with no samples.
  double quantile_ns(double q) const {
    if (count_ == 0) return 0.0;
    const auto rank = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_)));
    std::uint64_t seen = 0;
    for (std::size_t i = 0; i < counts_.size(); ++i) {
      seen += counts_[i];
      if (seen >= std::max<std::uint64_t>(rank, 1)) return bucket_middle_ns(i);
    }
    return static_cast<double>(max_ns_);
  }

 private:
  static constexpr std::uint64_t kExact = 1024;
  static constexpr std::uint64_t kHalf = kExact / 2;
  static constexpr std::uint64_t kMaxValueNs = (std::uint64_t{1} << 40) - 1;  // ~18 min
  static constexpr std::size_t kBuckets = kExact + 30 * kHalf;

  static std::size_t index_of(std::uint64_t ns) {
    if (ns < kExact) return static_cast<std::size_t>(ns);
    const auto shift = static_cast<unsigned>(std::bit_width(ns)) - 10U;  // >= 1
    return static_cast<std::size_t>(kExact + (shift - 1U) * kHalf + ((ns >> shift) - kHalf));
  }
  static double bucket_middle_ns(std::size_t index) {
    if (index < kExact) return static_cast<double>(index);
    const std::uint64_t k = index - kExact;
    const std::uint64_t shift = k / kHalf + 1U;
    const std::uint64_t low = (k % kHalf + kHalf) << shift;
    return static_cast<double>(low) + static_cast<double>((std::uint64_t{1} << shift) - 1U) / 2.0;
  }

  std::array<std::uint64_t, kBuckets> counts_{};
  std::uint64_t count_ = 0;
  std::uint64_t max_ns_ = 0;
};

}  // namespace rotctld_load
