#pragma once
// Each axis is read twice per frame (docs/encoder-hub.md): the two counts must agree within a few
// counts (the shaft may move a little between them) or the frame carries the Disagree error for it.
// So a transient glitch, a flipped bit on a long cable or a half-latched word is never a position.

#include <stdint.h>

#include "azt/proto/hub_frame.hpp"
#include "ssi_reading.hpp"

namespace azt {
namespace hub {

/// The shortest way round between two counts of a `bits`-bit encoder (0 and 2^bits − 1 are one
/// count apart).
constexpr uint16_t count_distance(uint16_t a, uint16_t b, uint8_t bits) {
  const uint32_t limit = proto::hub_raw_limit(bits);
  const uint32_t d = a > b ? static_cast<uint32_t>(a - b) : static_cast<uint32_t>(b - a);
  return static_cast<uint16_t>(d * 2U > limit ? limit - d : d);
}

/// The first reading if both are good and within `max_counts`; otherwise the first one's error,
/// the second's, or Disagree.
constexpr SsiCount agreed_count(SsiCount first, SsiCount second, uint8_t bits,
                                uint16_t max_counts) {
  if (first.error != proto::HubAxisError::None) return first;
  if (second.error != proto::HubAxisError::None) return second;
  if (count_distance(first.raw, second.raw, bits) > max_counts) {
    return SsiCount{0, proto::HubAxisError::Disagree};
  }
  return first;
}

}  // namespace hub
}  // namespace azt
